// Image headers (source/image_header.h), read before any decoding: any
// bytes give a size of at least 1 x 1 or none, and no byte past the end is
// read (ASan, and libFuzzer's exact-size buffers, see one).
#include "fuzz_support.h"
#include "source/image_header.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto image = ws::ImageHeaderSize(data, size);
  if (image && (image->width < 1 || image->height < 1))
    ws::fuzz::Violated("ImageHeaderSize gave a size below 1 x 1");
  return 0;
}
