// A file of the page (index.html, view.js, three.js ...) as stereo-view serves
// it: gzip-compressed once, when it starts, and sent as it is to every
// browser that accepts gzip (plain to the others), never compressed again
// per request: brotli of three.min.js alone costs the robot over a second of
// CPU each time a page is opened.
#pragma once

#include <string>

#include "view/http_server.h"

namespace ws::view {

class StaticAsset {
 public:
  StaticAsset(std::string body, std::string content_type);
  // Fills `res` with the file, gzip-encoded when `req` accepts it. The file
  // is not copied: the asset outlives the server.
  void Serve(const HttpHead& req, HttpResponse& res) const;

 private:
  std::string plain_, gzip_, content_type_;
};

}  // namespace ws::view
