// A frame with one of everything the renderer draws, for the renderer's tests.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "render/camera.h"
#include "render/frame.h"
#include "render/style.h"

namespace lamina::render::testing {

// Small frames keep the tests fast, also under the sanitizers.
inline constexpr FrameSize test_size{320, 180};

// Bodies, ground, a joint, new and kept contacts with forces, arrows, a path, labels,
// 3D items, a panel and the legend: every painter has work to do.
inline Frame full_frame() {
  Frame f;
  f.caption = "Fig 4-3  test frame";
  f.status = "t = 0.500 s · step 30";
  f.grounds.push_back({Vec2(0.0, 0.0), Vec2(0.0, 1.0)});
  f.paths.push_back({{Vec2(-3.0, 0.5), Vec2(-2.0, 1.5), Vec2(-1.0, 1.8)}, palette::grey, true});
  Body box;
  box.centre = Vec2(0.0, 0.5);
  box.angle = 0.3;
  box.velocity = Vec2(1.0, 0.5);
  f.bodies.push_back(box);
  Body disc;
  disc.shape = Body::Shape::circle;
  disc.centre = Vec2(2.0, 1.5);
  disc.radius = 0.4;
  disc.angle = 1.0;
  disc.fill = tint(palette::orange, 0.35);
  f.bodies.push_back(disc);
  f.joints.push_back({Vec2(2.0, 3.0), Vec2(2.0, 1.5)});
  f.contacts.push_back({Vec2(-0.5, 0.0), Vec2(0.0, 1.0), 40.0, Vec2(1.0, 0.0), -8.0, Contact::Origin::fresh});
  f.contacts.push_back({Vec2(0.5, 0.0), Vec2(0.0, 1.0), 25.0, Vec2(1.0, 0.0), 0.0, Contact::Origin::kept});
  f.arrows.push_back({Vec2(-2.0, 2.0), Vec2(-1.0, 2.5), palette::vermillion, "F", std::nullopt});
  f.labels.push_back({Vec2(0.0, 2.5), "ω × r", palette::ink, Label::Align::centre});
  // 3D items, drawn by the default cabinet projection, clear of the box.
  f.paths3.push_back(
      {{Vec3(2.5, 2.5, 0.0), Vec3(3.0, 2.5, 0.0), Vec3(3.0, 2.5, 1.0)}, palette::grey, true});
  f.arrows3.push_back({Vec3(2.8, 0.3, 0.0), Vec3(2.8, 0.3, 1.0), palette::reddish_purple, "τ"});
  f.points3.push_back({Vec3(-2.5, 2.5, 0.5), palette::vermillion, "rᵢ"});
  f.labels3.push_back({Vec3(3.0, 2.5, 1.0), "z", palette::ink, Label::Align::right});
  f.panels.push_back({Corner::top_left, "numbers", palette::blue, {"λ = 40.000 N", "W = 0"}});
  f.legend.push_back({LegendEntry::Sample::swatch, box.fill, "box"});
  return f;
}

// The camera the harness would fit for the test frame's world region.
inline Camera test_camera(const Overlays& overlays) {
  const Style style = Style::for_size(test_size);
  return Camera::fit({Vec2(-3.5, -0.5), Vec2(3.5, 3.2)},
                     style.drawing_area(test_size, overlays.has(Overlay::axes)));
}

// A fresh, empty folder under the system's temporary folder, removed when it goes out of scope.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("lamina-" + name + "-" + std::to_string(getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace lamina::render::testing
