// Replays fuzz inputs without libFuzzer: every file under the directories given on the
// command line, then N seeded pseudo-random inputs (--random N, lengths 0..512), each
// mutated from a corpus file when there is one. A failing input aborts (the target calls
// std::abort), so CTest reports it; once fixed, keep it in tests/regress/fuzz/CORPUS/.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "fuzz_target.hpp"

int main(int argc, char** argv) {
  std::vector<std::vector<std::uint8_t>> corpus;
  long random_inputs = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--random") == 0 && i + 1 < argc) {
      random_inputs = std::atol(argv[++i]);
      continue;
    }
    for (const auto& e : std::filesystem::recursive_directory_iterator(argv[i])) {
      if (!e.is_regular_file()) continue;
      std::ifstream in(e.path(), std::ios::binary);
      corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
  }
  for (const auto& input : corpus) LLVMFuzzerTestOneInput(input.data(), input.size());
  std::mt19937_64 rng(12345);
  for (long n = 0; n < random_inputs; ++n) {
    std::vector<std::uint8_t> input;
    if (!corpus.empty() && rng() % 4 != 0) {
      input = corpus[rng() % corpus.size()];
      const int edits = 1 + static_cast<int>(rng() % 8);
      for (int e = 0; e < edits && !input.empty(); ++e) {
        const std::size_t at = rng() % input.size();
        switch (rng() % 3) {
          case 0: input[at] = static_cast<std::uint8_t>(rng()); break;
          case 1: input.erase(input.begin() + static_cast<long>(at)); break;
          default: input.insert(input.begin() + static_cast<long>(at), input[rng() % input.size()]);
        }
      }
    } else {
      input.resize(rng() % 513);
      for (auto& b : input) b = static_cast<std::uint8_t>(rng());
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
  }
  std::printf("replayed %zu corpus inputs and %ld random inputs\n", corpus.size(), random_inputs);
  return 0;
}
