// stereo-view's request heads (view/http_head.h), as they arrive: the whole
// input and its first half, parsed alike whenever the half already holds a
// complete head, and never a head longer than the limits.
#include <cstdlib>
#include <string_view>

#include "view/http_head.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using ws::view::HeadParse;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const HeadParse whole = ws::view::ParseHead(bytes), half = ws::view::ParseHead(bytes.substr(0, size / 2));
  if (whole.state == HeadParse::State::kDone) {
    if (whole.length > size || whole.length > ws::view::kMaxHead) std::abort();
    (void)whole.head.Param("view");
    (void)whole.head.KeepAlive();
  }
  // What has come decides: more bytes never change a head already complete or refused.
  if (half.state != HeadParse::State::kIncomplete &&
      (half.state != whole.state || half.length != whole.length || half.status != whole.status))
    std::abort();
  return 0;
}
