// Whole-file input: every reader loads its file into memory once and parses the bytes in
// place (no iostreams in the hot loop). A file that cannot be opened or read is an
// InputError at line 0 naming the file and the system's reason.
#pragma once

#include <string>

namespace pdr::io {

// The bytes of `path`. Throws InputError(path, 0, ...) when it cannot be read.
std::string read_file_bytes(const std::string& path);

// True when `path` names an existing regular file.
bool is_regular_file(const std::string& path);

// The extension of `path` in lower case, with its dot (".ele"), or "" when none.
std::string lower_extension(const std::string& path);

// `path` without its extension (the part after the last dot of the file name).
std::string strip_extension(const std::string& path);

}  // namespace pdr::io
