// write_seed_corpus <folder>: every built-in scene as a scene file, <folder>/<name>.json, the
// seeds from which scene_fuzzer starts (beside the bad-scene catalogue and the regressions).
// The 20-row pyramid (63 kB, 210 bodies) and the 10-row hexagon pyramid are past the fuzzer's
// bounds (run_fuzzer.sh), so a 4-row and a 3-row one are written too.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "output/output_file.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_seed_corpus <folder>\n");
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  try {
    std::vector<std::string> names = {"pyramid:4", "hexagon-pyramid:3"};
    for (const lamina::BuiltinScene& entry : lamina::builtin_scene_list()) {
      names.push_back(entry.name);
    }
    for (const std::string& name : names) {
      std::string file_name = name + ".json";
      std::replace(file_name.begin(), file_name.end(), ':', '-');  // pyramid:4 → pyramid-4.json
      lamina::OutputFile file(folder / file_name);
      file.write(lamina::scene_to_json(lamina::builtin_scene(name)));
      file.commit();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_seed_corpus: %s\n", e.what());
    return 1;
  }
  return 0;
}
