#pragma once
// Checks a path a parser is about to read, so every reader reports a missing
// file or a directory the same way: "PATH: no such file", "PATH: is a
// directory, not a KIND file".

#include <string>

namespace repose {

// Throws InputError unless path names an existing regular file (or a link to one).
void require_regular_file(const std::string& path, const char* kind);

}  // namespace repose
