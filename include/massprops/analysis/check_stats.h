#pragma once
/// @file
/// What one `CheckModel` call measured: how often its expensive whole-model measurements were
/// taken. Counts, not times (a loaded machine cannot change them): for the tests that show a
/// rule that is off costs nothing, and for benchmarks.

#include <cstddef>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/model/model.h"

namespace massprops {

/// The measurements of one CheckModel call. A rule that is off takes none of its own.
struct CheckStats {
  /// Whole-model geometry extents built for inertia-exceeds-model (one per kinematic tree whose
  /// extent is known).
  std::size_t model_extents = 0;
  /// Links measured against the whole model's geometry (inertia-exceeds-model).
  std::size_t model_reach_measurements = 0;
  /// Distances from a center of mass to a corner of the model's geometry that those
  /// measurements evaluated (a scan of every corner for every link would be 8 n per link).
  std::size_t model_reach_distances = 0;
  /// Pairs of links judged as mirror images (com-not-mirrored).
  std::size_t mirrored_pairs = 0;
  /// Groups of links carrying the same typed-in numbers whose assemblies were measured
  /// (units-suspect's copied placeholders).
  std::size_t copied_groups = 0;
  /// Links whose whole geometry was measured (hull, support function, bounding ellipsoid) for
  /// the bounds of density_realizable.cc.
  std::size_t link_measures = 0;
  /// Welded-group composites the rules asked for (each member of a group may ask), and those
  /// composed: at most one per group.
  std::size_t group_composite_questions = 0;
  std::size_t group_composites = 0;
  /// What is outboard of a link, asked (massless-moving-body) and composed: every link's subtree
  /// at most once, from its children's, whatever the number of questions.
  std::size_t outboard_questions = 0;
  std::size_t subtree_composites = 0;
  /// How far its welded group's geometry reaches from a link, asked (units-suspect, for a link
  /// its own geometry does not size), and the groups whose corners were indexed for it: one each.
  std::size_t group_reach_questions = 0;
  std::size_t group_corner_indexes = 0;
};

/// CheckModel(model, options), and what it measured in `*stats` (set, not added to; nullptr:
/// not reported).
std::vector<Finding> CheckModel(const Model& model, const CheckOptions& options, CheckStats* stats);

}  // namespace massprops
