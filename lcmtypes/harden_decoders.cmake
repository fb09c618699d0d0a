# Run after lcm-gen: cmake -DDIR=<generated C++ header folder> -P harden_decoders.cmake
#
# LCM 1.3.1's generated decoders size every array from its length field before
# they check the buffer, so a message of a few bytes can claim billions of
# elements and make the receiver allocate gigabytes (or abort). Every encoded
# array element takes at least one byte, so a length beyond the bytes left is
# a lie: this inserts that check before each such resize, making decode
# return -1 instead.
#
# Its string decoders take a length field L and the next L bytes as L - 1
# characters and a NUL without looking: L = INT32_MIN overflowed L - 1, L <= 0
# threw from std::string, and a NUL inside the string made the message
# re-encode shorter than getEncodedSize() (found by tests/fuzz). A string is
# now accepted only as L >= 1 bytes whose only NUL is the last.
file(GLOB headers ${DIR}/*.hpp)
set(checks 0)
set(strings 0)
foreach(header ${headers})
  file(READ ${header} text)
  string(REGEX MATCHALL "\\.resize\\(this->" found "${text}")
  list(LENGTH found n)
  math(EXPR checks "${checks} + ${n}")
  string(REGEX MATCHALL "if\\(__[A-Za-z0-9_]+ > maxlen - pos\\)" found "${text}")
  list(LENGTH found n)
  math(EXPR strings "${strings} + ${n}")
  string(REGEX REPLACE
    "if\\((__[A-Za-z0-9_]+) > maxlen - pos\\) return -1;"
    "if (\\1 < 1 || \\1 > maxlen - pos || memchr((const char*) buf + offset + pos, 0, size_t(\\1)) != (const char*) buf + offset + pos + \\1 - 1) return -1;  // widestereo: a string is its bytes and one NUL"
    text "${text}")
  string(REGEX REPLACE
    "\n([ ]*)(this->[A-Za-z0-9_]+(\\[a[0-9]+\\])?)\\.resize\\(this->([A-Za-z0-9_]+)\\);"
    "\n\\1if (this->\\4 < 0 || this->\\4 > maxlen - pos) return -1;  // widestereo: length exceeds payload\n\\1\\2.resize(this->\\4);"
    text "${text}")
  file(WRITE ${header} "${text}")
endforeach()
message(STATUS "lcmtypes: length checks added before ${checks} array resizes and ${strings} strings")
