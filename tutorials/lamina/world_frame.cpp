#include "lamina/world_frame.h"

#include <algorithm>
#include <iterator>

#include "contact_views.h"
#include "harness/body_view.h"

namespace lamina::cli {
namespace {

constexpr render::Colour fixed_fill = render::tint(render::palette::grey, 0.3);

int index_of(const Scene& scene, const std::string& name) {
  const auto at = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                               [&](const BodyDescription& b) { return b.name == name; });
  return static_cast<int>(std::distance(scene.bodies.begin(), at));
}

render::Body body_view(const RigidBody& body, const Shape& shape) {
  render::Body view = tutorial::box_view(body, shape.half_extents, render::Body().fill);
  if (view.fixed) view.fill = fixed_fill;
  if (!shape.is_box()) {
    view.shape = render::Body::Shape::circle;
    view.radius = shape.radius;
  }
  return view;
}

}  // namespace

std::vector<JointEnds> joint_ends(const Scene& scene, const World& world) {
  std::vector<JointEnds> ends;
  for (const JointDescription& joint : scene.joints) {
    const bool pin = joint.type == JointType::revolute;
    JointEnds e;
    for (int k = 0; k < 2; ++k) {
      e.bodies[k] = index_of(scene, joint.bodies[k]);
      const Vec2d& p = pin ? joint.anchor : joint.anchors[k];
      e.offsets[k] = planar_pose(world.bodies()[e.bodies[k]]).to_body(Vec2(p[0], p[1]));  // eq. 5-12
    }
    ends.push_back(e);
  }
  return ends;
}

render::Frame world_frame(const Scene& scene, const World& world, const std::vector<JointEnds>& joints) {
  render::Frame frame;
  frame.caption = scene.description.empty() ? scene.name : scene.name + " · " + scene.description;
  const std::vector<RigidBody>& bodies = world.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    frame.bodies.push_back(body_view(bodies[i], world.shape(static_cast<int>(i))));
  }
  for (const ContactInfo& c : world.contacts()) frame.contacts.push_back(tutorial::contact_view(c));
  for (const JointEnds& j : joints) {
    frame.joints.push_back({planar_pose(bodies[j.bodies[0]]).to_world(j.offsets[0]),   // eq. 1-25
                            planar_pose(bodies[j.bodies[1]]).to_world(j.offsets[1])});
  }
  return frame;
}

}  // namespace lamina::cli
