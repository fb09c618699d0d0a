// A file of the page (index.html, view.js, three.js ...) as stereo-view serves
// it: gzip-compressed once, when it starts, and sent as it is to every
// browser that accepts gzip (plain to the others). httplib would otherwise
// compress it again for every request: brotli of three.min.js alone costs
// the robot over a second of CPU each time a page is opened.
#pragma once

#include <string>

namespace httplib {
struct Request;
struct Response;
}  // namespace httplib

namespace ws::view {

class StaticAsset {
 public:
  StaticAsset(std::string body, std::string content_type);
  // Fills `res` with the file, gzip-encoded when `req` accepts it.
  void Serve(const httplib::Request& req, httplib::Response& res) const;

 private:
  std::string plain_, gzip_, content_type_;
};

}  // namespace ws::view
