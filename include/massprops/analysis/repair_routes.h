#pragma once
/// @file
/// The ways forward for one link of `massprops fix`: every repair that would work on it, with
/// what it would write where that can be computed, and whether physics backs it or it is a
/// guess. `fix` names them under a refused repair and under an error it leaves (fix_text.h), and
/// `fix --dry-run` shows what each would write, so that an engineer chooses without running fix
/// several times. Each computed route is planned and judged by PlanRepairs (repair.h) exactly as
/// `fix` with that option would be: a route is offered only when its repair passes the checks.

#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/model/model.h"

namespace massprops {

/// One way forward for a link.
struct RepairRoute {
  /// The options of `massprops fix` that take it ("--from-geometry=base", "--repair balance",
  /// "--apply massless-moving-body", "--mass base=KG"); "" for this run's own repair (no option
  /// needed) and for the route outside massprops (CAD or datasheet).
  std::string options;
  /// What it writes, a few words: "the geometry's inertia at the written mass".
  std::string what;
  /// Whether physics backs it (the nearest valid inertia, or the real part's numbers); false:
  /// a guess (a uniform solid, a material, equal moments, a unit slip).
  bool physics = false;
  /// Why it is physics or a guess, a few words: "a uniform solid", "the real part".
  std::string basis;
  /// What it would write (judged), in file order; empty where the values are not known (a
  /// mass the engineer gives, the CAD route).
  std::vector<Repair> repairs;
};

/// The routes for `link` of `model` (one of the models `fix` plans; `findings` = CheckModel of
/// it with the options `fix` uses; `options` = fix's RepairOptions). `written`, when not null,
/// is the repair this run writes for the link (listed first). Computed routes, in this order:
/// `--from-geometry=LINK` (the link's own geometry at its written mass, meshes through
/// options.shape), `--repair balance` (for inertia-not-physical), `--apply RULE` for each
/// heuristic rule of the link's findings that was not asked for; then, where a mass is the
/// question, `--mass LINK=KG` (a link with a positive mass) and `--material LINK=NAME` (a link with
/// meshes); last the CAD or datasheet route. A route that equals `written` is not repeated.
/// Never throws for a model the readers produced.
std::vector<RepairRoute> FindRepairRoutes(const Model& model, const std::vector<Finding>& findings,
                                          const std::string& link, const RepairOptions& options,
                                          const Repair* written = nullptr);

}  // namespace massprops
