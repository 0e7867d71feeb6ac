// InputError: bad input, reported as "file:line: problem. what to do." and exit code 2.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace pdr {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::size_t line, const std::string& problem)
      : std::runtime_error(format(file, line, problem)), file_(std::move(file)), line_(line) {}
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }

 private:
  static std::string format(const std::string& file, std::size_t line,
                            const std::string& problem) {
    if (line == 0) return file + ": " + problem;
    return file + ":" + std::to_string(line) + ": " + problem;
  }
  std::string file_;
  std::size_t line_;
};

}  // namespace pdr
