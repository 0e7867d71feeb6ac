// Whole-file input; see file_bytes.hpp.
#include "io/file_bytes.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

#include "io/error.hpp"

namespace pdr::io {

namespace {
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
}  // namespace

std::string read_file_bytes(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno) +
                                  "; check the path");
  if (!S_ISREG(st.st_mode))
    throw InputError(path, 0, "not a regular file; give the path of a mesh or domain file");
  std::unique_ptr<std::FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
  if (!f)
    throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno) +
                                  "; check the path and its permissions");
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  const std::size_t got = std::fread(bytes.data(), 1, bytes.size(), f.get());
  if (got != bytes.size() || std::ferror(f.get()))
    throw InputError(path, 0, "read error after " + std::to_string(got) +
                                  " bytes; check the disk or copy the file again");
  return bytes;
}

bool is_regular_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

namespace {
std::size_t extension_dot(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos) return std::string::npos;
  if (slash != std::string::npos && dot < slash) return std::string::npos;
  return dot;
}
}  // namespace

std::string lower_extension(const std::string& path) {
  const std::size_t dot = extension_dot(path);
  if (dot == std::string::npos) return {};
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string strip_extension(const std::string& path) {
  const std::size_t dot = extension_dot(path);
  return dot == std::string::npos ? path : path.substr(0, dot);
}

}  // namespace pdr::io
