// Scene files: strict validation with one clear line per problem, and exact round trips.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_json.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

const std::string bad_scenes = std::string(LAMINA_TEST_DATA_DIR) + "/bad_scenes/";

// What refuses the file, as `lamina check` says it: the reader (its form and ranges), or the
// engine when the scene's World is built (its physical rules), led by the JSON path.
std::string message_for(const std::string& path) {
  try {
    const Scene scene = read_scene_file(path);
    build_world(scene, world_settings(scene));
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::invalid_argument& e) {
    return path + ": " + e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_SUITE("SceneFiles") {
  TEST_CASE("every malformed scene in the catalogue is refused with its own message") {
    // The catalogue's expected.tsv pairs each file with the message it must give; the message
    // starts with the file's path so a lecturer can find the problem.
    std::ifstream table(bad_scenes + "expected.tsv");
    REQUIRE(table);
    std::string line;
    int cases = 0;
    while (std::getline(table, line)) {
      if (line.empty() || line[0] == '#') continue;
      const auto tab = line.find('\t');
      const std::string file = bad_scenes + line.substr(0, tab);
      const std::string expected = file + ": " + line.substr(tab + 1);
      CAPTURE(file);
      CHECK(message_for(file).rfind(expected, 0) == 0);
      ++cases;
    }
    CHECK(cases >= 25);  // issue 7: at least 25 malformed files, one per rule
  }

  TEST_CASE("a missing scene file is named in the message") {
    CHECK(message_for("/nonexistent/scene.json") == "/nonexistent/scene.json: cannot open the scene file");
  }

  TEST_CASE("the documented example reads with every default applied") {
    const Scene s = parse_scene(R"({"bodies": [
        {"name": "ground", "shape": {"type": "box", "half_extents": [20, 0.5]},
         "position": [0, -0.5], "static": true},
        {"name": "ball", "shape": {"type": "circle", "radius": 0.25}, "position": [3, 1]}]})",
                                "example");
    // Defaults stated in docs/scene-format.md.
    CHECK(s.step.gravity == Vec3(0.0, -9.8, 0.0));
    CHECK(s.step.dt == 1.0 / 60.0);
    CHECK(s.step.iterations == 10);
    CHECK(s.step.beta == 0.2);
    REQUIRE(s.bodies.size() == 2);
    CHECK(s.bodies[0].is_static);
    CHECK(s.bodies[1].shape.type == ShapeType::circle);
    CHECK(s.bodies[1].shape.radius == 0.25);
    CHECK(s.bodies[1].density == 1.0);
    CHECK(s.bodies[1].friction == 0.6);
    CHECK(s.bodies[1].restitution == 0.0);
    CHECK(s.bodies[1].angle == 0.0);
  }

  TEST_CASE("every built-in scene survives a write and a read unchanged") {
    // Identity: written JSON read back and written again is the same text, to the last digit.
    for (const BuiltinScene& entry : builtin_scene_list()) {
      CAPTURE(entry.name);
      const Scene scene = builtin_scene(entry.name);
      const std::string written = scene_to_json(scene);
      const Scene read_back = parse_scene(written, entry.name);
      CHECK(scene_to_json(read_back) == written);
      CHECK(read_back.bodies.size() == scene.bodies.size());
      CHECK(read_back.step.dt == scene.step.dt);
    }
  }

  TEST_CASE("numbers round-trip exactly") {
    Scene scene = builtin_scene("box-on-ground-tilted");
    scene.step.dt = 1.0 / 3.0;
    scene.bodies[1].angle = 0.1 + 0.2;  // 0.30000000000000004, not 0.3
    const Scene back = parse_scene(scene_to_json(scene), "round-trip");
    CHECK(back.step.dt == scene.step.dt);
    CHECK(back.bodies[1].angle == scene.bodies[1].angle);
  }

  TEST_CASE("a pyramid scene has rows(rows+1)/2 boxes placed touching") {
    const Scene s = builtin_scene("pyramid:4");
    CHECK(s.bodies.size() == 1 + 10);
    // The top box of 4 rows sits at y = 0.5 + 3 · 1.0 (unit boxes, ground top at y = 0).
    CHECK(s.bodies.back().position[1] == 3.5);
    CHECK_THROWS_AS(builtin_scene("pyramid:0"), SceneError);
    CHECK_THROWS_AS(builtin_scene("no-such-scene"), SceneError);
  }

  TEST_CASE("the scene families: NAME:P builds the member, NAME the default, bad P is refused") {
    // Masses are density × area (unit boxes: 1 m²; the ball: π r²), exact up to π's rounding.
    const auto build_world = [](const Scene& scene) {
      return lamina::build_world(scene, world_settings(scene));
    };
    const World stack = build_world(builtin_scene("vertical-stack:20"));
    CHECK(stack.bodies().size() == 1 + 20);
    CHECK(stack.bodies().back().x.y() == 19.5);  // unit boxes touching from y = 0: the 20th at 19.5
    CHECK(builtin_scene("vertical-stack").bodies.size() == 1 + 5);  // the default member

    const Scene heavy = builtin_scene("heavy-on-light:1000");
    CHECK(heavy.name == "heavy-on-light:1000");
    const World hw = build_world(heavy);
    CHECK(hw.bodies()[1].mass == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(hw.bodies()[2].mass == doctest::Approx(1000.0).epsilon(1e-15));
    // Placed exactly touching: the light box's top and the heavy box's bottom both at y = 1.
    CHECK(hw.bodies()[1].x.y() + 0.5 == hw.bodies()[2].x.y() - 0.5);

    const World chain = build_world(builtin_scene("ball-and-chain:100"));
    double links = 0.0;
    for (std::size_t i = 2; i + 1 < chain.bodies().size(); ++i) links += chain.bodies()[i].mass;
    CHECK(links == doctest::Approx(0.5).epsilon(1e-12));  // 10 links of 0.5 × 0.1 m², density 1
    const RigidBody& ball = chain.bodies().back();
    CHECK(ball.mass == doctest::Approx(100.0 * 0.5).epsilon(1e-12));
    // The issue's rest distance from the fixed pin (0, 10) to the ball's centre: 5 m of chain
    // plus the 0.5 m radius.
    CHECK((ball.x - Vec3(0.0, 10.0, 0.0)).norm() == doctest::Approx(5.5).epsilon(1e-15));
    CHECK(chain.joint_count() == 11);

    for (const char* bad : {"heavy-on-light:0", "pyramid:2.5", "ball-and-chain:x", "vertical-stack:",
                            "vertical-stack:1001", "heavy-on-light:nan"}) {
      CHECK_THROWS_AS(builtin_scene(bad), SceneError);
    }
  }
}
