// The three ways a tutorial runs: rendering frames, writing the step-through viewer, or
// explaining steps as text or JSON.
#pragma once

#include "app/harness/tutorial.h"

namespace lamina::tutorial {

// Renders every scene's frames into options.out, then its data; prints one line per scene.
void render_scenes(const TutorialInfo& info, const Options& options,
                   const std::vector<SceneFactory>& scenes);

// --viewer DIR: the step-through page of every scene, each step of the span its frames cover.
void view_scenes(const TutorialInfo& info, const Options& options,
                 const std::vector<SceneFactory>& scenes);

// --explain STEP / --step-through: prints what each scene computed, renders nothing.
void explain_scenes(const TutorialInfo& info, const Options& options,
                    const std::vector<SceneFactory>& scenes);

}  // namespace lamina::tutorial
