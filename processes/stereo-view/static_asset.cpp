#include "static_asset.h"

#include <zlib.h>

#include <stdexcept>

namespace ws::view {
namespace {

// RFC 1952 gzip of `text` (zlib's deflate, windowBits 15 + 16 for the gzip wrapper).
std::string Gzip(const std::string& text) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: cannot start compressing the page");
  std::string out(deflateBound(&z, text.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int done = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (done != Z_STREAM_END) throw std::runtime_error("zlib: cannot compress the page");
  return out;
}

}  // namespace

StaticAsset::StaticAsset(std::string body, std::string content_type)
    : plain_(std::move(body)), gzip_(Gzip(plain_)), content_type_(std::move(content_type)) {}

void StaticAsset::Serve(const HttpHead& req, HttpResponse& res) const {
  const bool gzip = req.Field("accept-encoding").find("gzip") != std::string::npos;
  if (gzip) res.fields.emplace_back("Content-Encoding", "gzip");
  res.fields.emplace_back("Vary", "Accept-Encoding");
  res.content_type = content_type_;
  res.shared_body = gzip ? gzip_ : plain_;
}

}  // namespace ws::view
