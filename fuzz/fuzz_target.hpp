// The libFuzzer entry point every fuzz target defines. Built with clang and
// -fsanitize=fuzzer when PDR_FUZZ=ON; otherwise linked with replay_main.cpp, which replays
// the corpus and a seeded stream of random inputs as a CTest test (label "fuzz").
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
