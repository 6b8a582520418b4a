// Box2D v3's headers are C and name their types as Box2D 2.4.1's do (b2Vec2, box2d/box2d.h): this
// file is the only one that includes them, compiled on its own (out of the unity build) with
// v3's include folder first.
#include "benchmarks/box2d_v3_runs.h"

#include <box2d/box2d.h>

#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace lamina {
namespace {

// v3's world built from the Scene: its bodies in the Scene's order.
struct V3World {
  b2WorldId world = b2_nullWorldId;
  std::vector<b2BodyId> bodies;

  explicit V3World(const Scene& scene) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = {static_cast<float>(scene.step.gravity.x()), static_cast<float>(scene.step.gravity.y())};
    def.enableSleep = false;       // a sleeping body reports no motion (as for Box2D 2.4.1)
    def.enableContinuous = false;  // Lamina has none
    def.workerCount = 1;           // one thread, no task system
    world = b2CreateWorld(&def);
    for (const BodyDescription& d : scene.bodies) {
      if (d.shape.type != ShapeType::box) {
        throw std::invalid_argument("Box2D v3 benchmark: only boxes (body '" + d.name + "')");
      }
      b2BodyDef body = b2DefaultBodyDef();
      body.type = d.is_static ? b2_staticBody : b2_dynamicBody;
      body.position = {static_cast<float>(d.position.x()), static_cast<float>(d.position.y())};
      body.rotation = b2MakeRot(static_cast<float>(d.angle));
      const b2BodyId id = b2CreateBody(world, &body);
      b2ShapeDef shape = b2DefaultShapeDef();
      shape.density = static_cast<float>(d.density);
      shape.material.friction = static_cast<float>(d.friction);
      shape.material.restitution = static_cast<float>(d.restitution);
      const b2Polygon box = b2MakeBox(static_cast<float>(d.shape.half_extents.x()),
                                      static_cast<float>(d.shape.half_extents.y()));
      b2CreatePolygonShape(id, &shape, &box);
      bodies.push_back(id);
    }
  }
  ~V3World() { b2DestroyWorld(world); }
  V3World(const V3World&) = delete;
  V3World& operator=(const V3World&) = delete;

  // Manifold points of every touching contact, each contact counted once.
  int contact_points() const {
    std::set<std::pair<int, int>> seen;
    std::vector<b2ContactData> data;
    int points = 0;
    for (const b2BodyId body : bodies) {
      data.resize(static_cast<std::size_t>(b2Body_GetContactCapacity(body)));
      const int count = b2Body_GetContactData(body, data.data(), static_cast<int>(data.size()));
      for (int k = 0; k < count; ++k) {
        const b2ContactData& c = data[static_cast<std::size_t>(k)];
        if (seen.insert({c.shapeIdA.index1, c.shapeIdB.index1}).second) points += c.manifold.pointCount;
      }
    }
    return points;
  }
};

}  // namespace

std::string box2d_v3_version() {
  const b2Version v = b2GetVersion();
  return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.revision);
}

PyramidRun run_box2d_v3_pyramid(int base, int substeps) {
  const Scene scene = pyramid_of(PyramidShape::boxes, base);
  V3World v3(scene);
  const float dt = static_cast<float>(scene.step.dt);
  const auto where = [&] {
    Positions p;
    for (const b2BodyId body : v3.bodies) {
      const b2Vec2 x = b2Body_GetPosition(body);
      p.push_back({x.x, x.y});
    }
    return p;
  };
  const auto count_rows = [&](PyramidRun& run) {
    run.contact_points = v3.contact_points();
    run.velocity_rows = 2 * run.contact_points;  // a normal and a friction row per point
    run.position_rows = 0;                       // no position pass: the soft step's bias
    run.velocity_iterations = substeps;          // one solve per substep (and a relax)
    run.position_iterations = 0;
  };
  return measure_pyramid_run(scene, [&] { b2World_Step(v3.world, dt, substeps); }, where, count_rows);
}

}  // namespace lamina
