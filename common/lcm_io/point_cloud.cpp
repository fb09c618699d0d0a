#include "lcm_io/point_cloud.h"

#include <cstring>

#include <lcm/lcm_coretypes.h>

#include "lcm_io/validate.h"
#include "widestereo/point_cloud_t.hpp"

namespace ws {

static_assert(sizeof(std::array<float, 3>) == 3 * sizeof(float), "a point's coordinates must be contiguous");

const char* PointCloud::getTypeName() { return widestereo::point_cloud_t::getTypeName(); }

int64_t PointCloud::getHash() { return widestereo::point_cloud_t::getHash(); }

// The frame as the generated code encodes it: up to its first NUL.
int PointCloud::getEncodedSize() const {
  return 8 + 8 + 8 + 4 + int(std::strlen(frame.c_str())) + 1 + 4 + npoints * 12 + 4 + nintensity * 4;
}

int PointCloud::encode(void* buf, int offset, int maxlen) const {
  if (npoints < 0 || size_t(npoints) != xyz.size() || nintensity < 0 || size_t(nintensity) != intensity.size())
    return -1;
  int pos = 0;
  // Appends one field's encoding; false when it does not fit.
  auto put = [&](int length) {
    if (length < 0) return false;
    pos += length;
    return true;
  };
  const int64_t hash = getHash();
  char* frame_cstr = const_cast<char*>(frame.c_str());
  const bool encoded =
      put(__int64_t_encode_array(buf, offset + pos, maxlen - pos, &hash, 1)) &&
      put(__int64_t_encode_array(buf, offset + pos, maxlen - pos, &utime, 1)) &&
      put(__int64_t_encode_array(buf, offset + pos, maxlen - pos, &frame_id, 1)) &&
      put(__string_encode_array(buf, offset + pos, maxlen - pos, &frame_cstr, 1)) &&
      put(__int32_t_encode_array(buf, offset + pos, maxlen - pos, &npoints, 1)) &&
      (npoints == 0 || put(__float_encode_array(buf, offset + pos, maxlen - pos, xyz.front().data(), 3 * npoints))) &&
      put(__int32_t_encode_array(buf, offset + pos, maxlen - pos, &nintensity, 1)) &&
      (nintensity == 0 || put(__float_encode_array(buf, offset + pos, maxlen - pos, intensity.data(), nintensity)));
  return encoded ? pos : -1;
}

int PointCloud::decode(const void* buf, int offset, int maxlen) {
  const char* bytes = static_cast<const char*>(buf) + offset;
  int pos = 0;
  // One field of n elements at pos, each `size` bytes; false when it
  // would run past the buffer.
  auto fits = [&](int64_t n, int size) { return n >= 0 && n <= (maxlen - pos) / size; };
  int64_t hash;
  if (!fits(3, 8) || __int64_t_decode_array(buf, offset, maxlen, &hash, 1) < 0 || hash != getHash()) return -1;
  __int64_t_decode_array(buf, offset + 8, maxlen - 8, &utime, 1);
  __int64_t_decode_array(buf, offset + 16, maxlen - 16, &frame_id, 1);
  pos = 24;
  int32_t frame_length;  // its bytes and a NUL, the only one
  if (!fits(1, 4)) return -1;
  pos += __int32_t_decode_array(buf, offset + pos, maxlen - pos, &frame_length, 1);
  if (frame_length < 1 || !fits(frame_length, 1) ||
      std::memchr(bytes + pos, 0, size_t(frame_length)) != bytes + pos + frame_length - 1)
    return -1;
  frame.assign(bytes + pos, size_t(frame_length - 1));
  pos += frame_length;
  if (!fits(1, 4)) return -1;
  pos += __int32_t_decode_array(buf, offset + pos, maxlen - pos, &npoints, 1);
  if (!fits(npoints, 12)) return -1;
  xyz.resize(size_t(npoints));
  if (npoints > 0) pos += __float_decode_array(buf, offset + pos, maxlen - pos, xyz.front().data(), 3 * npoints);
  if (!fits(1, 4)) return -1;
  pos += __int32_t_decode_array(buf, offset + pos, maxlen - pos, &nintensity, 1);
  if (!fits(nintensity, 4)) return -1;
  intensity.resize(size_t(nintensity));
  if (nintensity > 0) pos += __float_decode_array(buf, offset + pos, maxlen - pos, intensity.data(), nintensity);
  return pos;
}

void Validate(const PointCloud& msg) {
  // The generated type's rule, on a message of the same counts.
  widestereo::point_cloud_t counts;
  counts.npoints = msg.npoints;
  counts.nintensity = msg.nintensity;
  Validate(counts);
}

}  // namespace ws
