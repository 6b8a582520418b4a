// How PGS's rows are cut into parts (threads, or two lanes on one thread) and where each part
// waits on another (pgs_solver.h): made from the MLCP's groups (Mlcp::groups), its row count and
// the number of parts. The parts and the waits are counted in groups, and the waits follow from
// the groups' bodies alone, so a plan serves every MLCP whose groups are on the same bodies in
// the same order, whatever their rows: a step's position MLCP (its velocity MLCP's contact rows,
// a group for each pair in both) is swept by its velocity MLCP's plan, and a pile at rest keeps
// its contact pairs, and so its plan, step after step. Only the cut between the parts, made by
// rows, would have fallen a little elsewhere; any cut gives the same λ.
#pragma once

#include <array>
#include <vector>

#include "constraints/mlcp.h"

namespace lamina {

// Whether a plan of `parts` parts is one thread's two lanes: on threads each thread takes two
// parts (runs_on), four or more. The lanes need fewer rows and bear more waits than threads,
// whose hand-overs cross cores (PgsSolver::lanes_min_rows, part_plan.cpp).
inline bool lanes_of_one_thread(int parts) { return parts == 2; }

class PartPlan {
 public:
  // Where the part (thread or lane) of a group waits before its pass k over it, for each of its
  // bodies whose group before it (in the one-thread order) another part takes: until `part` has
  // passed k·G + `after` (G groups a pass; `after` ≤ 0 for a group of the pass before).
  struct GroupWait {
    std::array<int, 2> part{-1, -1};
    std::array<long, 2> after{0, 0};
  };

  // Whether this plan serves `mlcp` in `parts` parts: it was made for `parts` parts and groups
  // on the same bodies, in the same order, as `mlcp`'s.
  bool serves(const Mlcp& mlcp, int parts) const;
  // Cuts the groups into `parts` parts of consecutive groups, each about its share of the rows,
  // and finds the waits between them. Returns usable().
  bool make(const Mlcp& mlcp, int parts);

  // False when the parts would wait on each other too often (then one part is faster).
  bool usable() const { return usable_; }
  int parts() const { return parts_; }  // how many parts it cuts the groups into
  // Part t takes the groups [first_group(t), first_group(t + 1)).
  int first_group(int part) const { return part_first_[static_cast<std::size_t>(part)]; }
  // Where group g waits, or nullptr when it waits on no other part (most groups do not).
  const GroupWait* wait_of(int group) const {
    const int k = wait_index_[static_cast<std::size_t>(group)];
    return k < 0 ? nullptr : &waits_[static_cast<std::size_t>(k)];
  }
  // How far a part that may take group g may go on in one run, without looking at a wait: to
  // the group after the first from g on that another part waits for (its part then publishes
  // its progress), or to the first after g that waits itself, whichever comes first. Not cut at
  // the part's end, which its caller knows.
  int run_end(int group) const { return run_end_[static_cast<std::size_t>(group)]; }
  // Whether another part waits for group g: then its part publishes its progress past it.
  bool waited_on(int group) const { return waited_on_[static_cast<std::size_t>(group)] != 0; }

 private:
  // what the plan was made for: each group's bodies, and the parts
  std::vector<std::array<int, 2>> bodies_;
  int parts_ = 0;
  // the plan
  bool usable_ = false;
  std::vector<int> part_first_;
  std::vector<int> wait_index_;           // per group, its wait in waits_, or −1: none
  std::vector<GroupWait> waits_;          // the waits of the groups that wait, in group order
  std::vector<unsigned char> waited_on_;  // another part waits for group g
  std::vector<int> run_end_;              // per group, run_end()
  std::vector<int> last_group_of_body_;   // scratch of make(): the last group met on each body
};

}  // namespace lamina
