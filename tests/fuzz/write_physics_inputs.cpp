// write_physics_inputs <folder> [count]: the fixed inputs CI's fuzz_physics runs, <count> files
// (2000 unless told) <folder>/input-NNNNN of bytes for the physics fuzzer's grammar
// (support/scene_generator.h), drawn by std::mt19937 from seed 27, so every machine runs the same
// scenes and a red run is repeated exactly by running its input again. A length from 8 to 512
// bytes, even in its logarithm (short inputs make small scenes, long ones up to the grammar's 8
// bodies); one stretch in four is a byte repeated, as libFuzzer's InsertRepeatedBytes makes:
// equal bodies placed in a row, the same value in every field, the structured scenes random bytes
// alone rarely give.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "output/output_file.h"

int main(int argc, char** argv) {
  char* end = nullptr;
  const long count = argc == 3 ? std::strtol(argv[2], &end, 10) : 2000;
  if (argc < 2 || argc > 3 || (argc == 3 && *end != '\0') || count < 1 || count > 1000000) {
    std::fprintf(stderr, "usage: write_physics_inputs <folder> [count in [1, 1000000], 2000]\n");
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  try {
    std::filesystem::create_directories(folder);
    std::mt19937 rng(27);
    auto uniform = [&rng](int low, int high) {  // a whole number in [low, high]
      return low + static_cast<int>(rng() % static_cast<unsigned>(high - low + 1));
    };
    for (long k = 0; k < count; ++k) {
      const int length = static_cast<int>(std::lround(8.0 * std::pow(64.0, (rng() % 10001) / 10000.0)));
      std::string bytes;
      while (static_cast<int>(bytes.size()) < length) {
        const int stretch = uniform(1, 32);
        if (uniform(0, 3) == 0) {
          bytes.append(static_cast<std::size_t>(stretch), static_cast<char>(uniform(0, 255)));
        } else {
          for (int i = 0; i < stretch; ++i) bytes.push_back(static_cast<char>(uniform(0, 255)));
        }
      }
      bytes.resize(static_cast<std::size_t>(length));
      char name[32];
      std::snprintf(name, sizeof name, "input-%05ld", k);
      lamina::OutputFile file(folder / name);
      file.write(bytes);
      file.commit();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_physics_inputs: %s\n", e.what());
    return 1;
  }
  return 0;
}
