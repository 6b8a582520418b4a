// The MLCP of eq. 3-16 assembled as the contact rows are written (Mlcp::assemble with a
// RowWriter, the way a World assembles it) against the MLCP of the same rows written first as
// ConstraintRows (add_contact_rows) and assembled from that vector. Both pack every row by the
// same arithmetic, so every number must be equal bit for bit (tolerance 0), and so must the
// groups of rows on the same bodies, the layout and where each pair's rows went — on one
// thread and on teams of 2 and 3, whose runs cut the rows among pairs on the same bodies.
#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "contact/contact_rows.h"
#include "contact/world.h"
#include "parallel/workers.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_world.h"

using namespace lamina;

namespace {

// Equal bit for bit (a -0.0 and a 0.0 differ).
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec6& a, const Vec6& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 6) == 0;
}

// The layout's components per block: 3 (planar) or 6.
int layout(const Mlcp& mlcp) {
  return mlcp.visit(
      [](const auto& rows) { return std::decay_t<decltype(rows)>::value_type::size; });
}

// Every number and group of `a` equals `b`'s.
void check_same(const Mlcp& a, const Mlcp& b) {
  REQUIRE(a.row_count() == b.row_count());
  CHECK(layout(a) == layout(b));
  CHECK(a.friction_on_own_bodies() == b.friction_on_own_bodies());
  const std::vector<double> lambda(static_cast<std::size_t>(a.row_count()), 0.5);
  for (int i = 0; i < a.row_count(); ++i) {
    CAPTURE(i);
    CHECK(a.bodies_of(i) == b.bodies_of(i));
    for (int k = 0; k < 2; ++k) {
      CHECK(same_bits(a.jacobian(i, k), b.jacobian(i, k)));
      CHECK(same_bits(a.b_block(i, k), b.b_block(i, k)));
    }
    CHECK(same_bits(a.eta(i), b.eta(i)));
    CHECK(same_bits(a.d(i), b.d(i)));
    CHECK(same_bits(a.zeta(i), b.zeta(i)));
    CHECK(a.friction_of(i) == b.friction_of(i));
    CHECK(a.friction_count(i) == b.friction_count(i));
    CHECK(same_bits(a.mu(i), b.mu(i)));
    CHECK(same_bits(a.bounds(i, lambda.data())[0], b.bounds(i, lambda.data())[0]));
    CHECK(same_bits(a.bounds(i, lambda.data())[1], b.bounds(i, lambda.data())[1]));
  }
  REQUIRE(a.groups().size() == b.groups().size());
  for (std::size_t g = 0; g < a.groups().size(); ++g) {
    CAPTURE(g);
    CHECK(a.groups()[g].first == b.groups()[g].first);
    CHECK(a.groups()[g].bodies == b.groups()[g].bodies);
  }
}

// A World after `steps` steps, its contact pairs and bodies taken as a step's rows would be.
struct Contacts {
  std::vector<ContactPair> pairs;
  std::vector<RigidBody> bodies;
};
Contacts contacts_after(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
  REQUIRE(!world.contact_pairs().empty());
  return {world.contact_pairs(), world.bodies()};
}

// A box bridging two static blocks, on a third: the pairs (0, 3), (1, 3) and (2, 3) all hold
// rows on the box alone (a static body holds no block), so a team's runs, which take them one
// each, cut a run of rows on the same body that the groups must join again.
Contacts bridge(const ContactSettings& contact) {
  WorldSettings settings;
  settings.contact = contact;
  World world(settings);
  world.add_static_box(0.5, 0.5, Vec3(-1.0, -0.5, 0.0));
  world.add_static_box(0.5, 0.5, Vec3(1.0, -0.5, 0.0));
  world.add_static_box(0.5, 0.5, Vec3(0.0, -0.5, 0.0));
  world.add_box(1.0, 1.5, 0.25, Vec3(0.0, 0.25, 0.0));
  return contacts_after(world, 3);
}

// The built-in pyramid of boxes `base` wide, with these contact settings.
Contacts pyramid(int base, const ContactSettings& contact) {
  const Scene scene = builtin_scene("pyramid:" + std::to_string(base));
  WorldSettings settings = world_settings(scene);
  settings.contact = contact;
  World world = build_world(scene, settings);
  return contacts_after(world, 20);
}

// Assembles `contacts`' rows both ways on `threads` threads (the vector way on one), with
// `extra` rows after them (as a World's joints' rows follow its contacts'), and checks that the
// two MLCPs, the warm-start λ and the pairs' row maps are the same.
void check_both_ways(const Contacts& contacts, const ContactSettings& settings, int threads,
                     const std::vector<ConstraintRow>& extra = {}) {
  const StepSettings step;
  std::vector<Vec6> unconstrained;
  unconstrained_velocities(contacts.bodies, step.dt, unconstrained);

  std::vector<ContactPair> listed = contacts.pairs;
  std::vector<ConstraintRow> rows;
  std::vector<double> listed_lambda;
  add_contact_rows(listed, contacts.bodies, settings, step, rows, listed_lambda);
  rows.insert(rows.end(), extra.begin(), extra.end());
  Mlcp from_vector;
  from_vector.assemble(contacts.bodies, rows, unconstrained, step.dt);

  std::vector<ContactPair> written = contacts.pairs;
  std::vector<double> lambda{1.0, 2.0};  // resized by the writer
  ContactRows writer(written, contacts.bodies, settings, step, lambda);
  Workers workers(threads);
  Mlcp as_written;
  as_written.assemble(contacts.bodies, writer, extra, unconstrained, step.dt,
                      threads > 1 ? &workers : nullptr);

  check_same(as_written, from_vector);
  CHECK(lambda == listed_lambda);
  REQUIRE(written.size() == listed.size());
  for (std::size_t p = 0; p < written.size(); ++p) {
    CHECK(written[p].rows.first == listed[p].rows.first);
    CHECK(written[p].rows.count == listed[p].rows.count);
    for (int k = 0; k < written[p].count; ++k) {
      CHECK(written[p].contacts[k].row == listed[p].contacts[k].row);
      CHECK(written[p].contacts[k].friction_rows == listed[p].contacts[k].friction_rows);
    }
  }
  // the text's form of each row, read back from the packed rows: the row as written
  for (int i = 0; i < as_written.row_count(); ++i) {
    const ConstraintRow row = as_written.row(i);
    const ConstraintRow& expected = rows[static_cast<std::size_t>(i)];
    CAPTURE(i);
    CHECK(row.Jmap == expected.Jmap);
    CHECK(row.Jsp[0] == expected.Jsp[0]);  // == : a cut −0.0 reads back as 0.0
    CHECK(row.Jsp[1] == expected.Jsp[1]);
    CHECK(same_bits(row.zeta, expected.zeta));
    CHECK(same_bits(row.lambda_min, expected.lambda_min));
    CHECK(same_bits(row.lambda_max, expected.lambda_max));
    CHECK(row.friction_of == expected.friction_of);
    CHECK(row.friction_count == expected.friction_count);
    CHECK(same_bits(row.mu, expected.mu));
  }
}

// A writer that passes another's rows on, counting how many it was given to write: a sink of
// its own puts them into the sink it was handed and says what that one says.
class Counting final : public RowWriter {
 public:
  explicit Counting(RowWriter& inner) : inner_(inner) {}
  std::size_t count(int t, int runs) override { return inner_.count(t, runs); }
  void begin(std::size_t total) override { inner_.begin(total); }
  void write(int t, int runs, RowSink& sink) override {
    Passing passing(sink, written_);
    inner_.write(t, runs, passing);
  }
  std::size_t written() const { return written_; }

 private:
  class Passing final : public RowSink {
   public:
    Passing(RowSink& to, std::size_t& written) : RowSink(to.next()), to_(to), written_(written) {}
    bool put(const ConstraintRow* rows, int count) override {
      written_ += static_cast<std::size_t>(count);
      const bool more = to_.put(rows, count);
      next_ = to_.next();
      return more;
    }

   private:
    RowSink& to_;
    std::size_t& written_;
  };
  RowWriter& inner_;
  std::size_t written_ = 0;
};

}  // namespace

TEST_CASE("contact rows packed as written: the MLCP of the same rows assembled from a vector") {
  const ContactSettings settings;
  const Contacts piled = pyramid(6, settings);
  for (const int threads : {1, 2, 3}) {
    CAPTURE(threads);
    check_both_ways(piled, settings, threads);
  }
}

TEST_CASE("a team's runs cut a run of rows on one body: its groups are joined as one") {
  const ContactSettings settings;
  const Contacts bridged = bridge(settings);
  REQUIRE(bridged.pairs.size() == 3);
  for (const int threads : {1, 2, 3}) {
    CAPTURE(threads);
    check_both_ways(bridged, settings, threads);
  }
  // a row after the written ones on their last bodies (as a joint's on the same body would be)
  // joins their last group too
  std::vector<ConstraintRow> rows;
  std::vector<double> lambda;
  std::vector<ContactPair> pairs = bridged.pairs;
  add_contact_rows(pairs, bridged.bodies, settings, StepSettings{}, rows, lambda);
  ConstraintRow same_bodies = rows.back();
  same_bodies.friction_of = -1;
  same_bodies.lambda_min = -1.0;
  same_bodies.lambda_max = 1.0;
  check_both_ways(bridged, settings, 2, {same_bodies});
}

TEST_CASE("a written row out of the plane: the rows are packed again in the general layout") {
  ContactSettings settings;
  settings.out_of_plane_friction = true;  // u2 = z: J's ω_x, ω_y are not zero
  const Contacts piled = pyramid(4, settings);
  for (const int threads : {1, 2}) {
    CAPTURE(threads);
    check_both_ways(piled, settings, threads);
  }
  const StepSettings step;
  std::vector<Vec6> unconstrained;
  unconstrained_velocities(piled.bodies, step.dt, unconstrained);
  std::vector<ContactPair> pairs = piled.pairs;
  std::vector<double> lambda;
  ContactRows writer(pairs, piled.bodies, settings, step, lambda);
  Counting counting(writer);
  Mlcp mlcp;
  mlcp.assemble(piled.bodies, counting, {}, unconstrained, step.dt);
  CHECK(layout(mlcp) == 6);
  // the planar packing stops the writing at the first pair (each pair has a u2 = z row): its
  // rows, then every row once in the general layout — not every row twice
  const std::size_t rows = static_cast<std::size_t>(mlcp.row_count());
  REQUIRE(pairs.size() > 2);
  CHECK(counting.written() == static_cast<std::size_t>(pairs.front().rows.count) + rows);
}
