// A shell glob matched against a file name, returning what each `*` matched,
// so that two globs can pair files: `*left*` and `*right*` pair
// /data/left-07.png with /data/right-07.png because both `*`s matched the
// same texts ("/data/", "-07.png"). mrcal-calibrate-cameras pairs its
// cameras' images the same way.
//
// The glob language is fnmatch's without FNM_PATHNAME: `*` matches any text
// (`/` included), `?` any one character, `[abc]`, `[a-z]` and `[!abc]` one
// character of (or not of) the set, and `\c` the character c itself. Where
// a `*` could match texts of several lengths, each `*` takes the shortest
// that lets the rest of the glob match, from left to right.
//
// A relative glob (not starting with `/`) also matches a name's trailing
// path components, as mrcal's does: `left*.png` matches /data/left-07.png.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ws::calib {

// The texts the `*`s of `glob` matched in `name`, in order; nullopt when it
// does not match. Throws std::invalid_argument for a glob with an unclosed `[`.
std::optional<std::vector<std::string>> GlobCaptures(const std::string& glob, const std::string& name);

// The number of `*` wildcards in `glob` (escaped and bracketed ones not counted).
int GlobStars(const std::string& glob);

}  // namespace ws::calib
