// The entry point of every chapter tutorial: parse the options, then render the scenes' frames
// (or explain their steps), and report any failure as one line with a non-zero exit code.
//
// A chapter tutorial is one .cpp whose main() is
//   return lamina::tutorial::run_tutorial(argc, argv, info, {make_scene_a, make_scene_b});
// and one line in tutorials/CMakeLists.txt: add_tutorial(NN_name STAGES <stage targets>).
// Scenes without options are listed as scene<MyScene>().
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "app/harness/options.h"
#include "app/harness/scene.h"

namespace lamina::tutorial {

using SceneFactory = std::function<std::unique_ptr<Scene>(const Options&)>;

// The factory of a scene made by its default constructor.
template <typename SceneType>
SceneFactory scene() {
  return [](const Options&) { return std::make_unique<SceneType>(); };
}

int run_tutorial(int argc, char** argv, const TutorialInfo& info,
                 const std::vector<SceneFactory>& scenes);

}  // namespace lamina::tutorial
