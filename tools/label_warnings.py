#!/usr/bin/env python3
"""Builds testdata/labels/warnings.tsv: one row per warning that `massprops check --format json`
gave on ../shared/corpus BEFORE issue 12 (commit ca2762f), judged real or noise by evidence class
(docs/labels.md explains each class and the examples read by hand).

Usage: tools/label_warnings.py BEFORE.json AFTER.json > testdata/labels/warnings.tsv
BEFORE.json / AFTER.json: the JSON reports of the old and the new tool over the corpus (the command
of tools/corpus_summary.py). AFTER is used only to tell which geometry warnings the union of the
collision and visual geometry of the welded group (or a mesh of unknown size) explains: those are
the 'partial-geometry' and 'lumped' classes; every such row was read by hand (docs/labels.md)."""
import json
import sys

before = json.load(open(sys.argv[1]))
after = json.load(open(sys.argv[2]))
still = set()
for e in after["files"]:
    for f in e["findings"]:
        still.add((e["path"], f["rule"], f["link"]))
# A units-suspect and an inertia-exceeds-geometry on the same link report the same defect (an
# inertia too large for the body); judged against the union of the geometry, one may replace the
# other.
SAME_DEFECT = {"units-suspect": "inertia-exceeds-geometry", "inertia-exceeds-geometry": "units-suspect"}


def g(v, k, default=0.0):
    return v.get(k, default)


print("file\trule\tlink\tlabel\twhy")
for e in before["files"]:
    for f in e["findings"]:
        rule, link, v = f["rule"], f["link"], f["values"]
        if f["severity"] != "warning" or rule in ("read-warning", "include-unresolved"):
            continue
        fires = (e["path"], rule, link) in still or (
            rule in SAME_DEFECT and (e["path"], SAME_DEFECT[rule], link) in still)
        label, why = "real", ""
        if rule == "units-suspect":
            m, e_, k, r = g(v, "mass"), g(v, "geometry_half_diagonal"), g(v, "radius_of_gyration"), g(v, "ratio")
            if m <= 1e-3:
                label, why = "noise", f"dummy mass {m:g} kg (<= 1 g): k = {k:.3g} m means nothing"
            elif 0 < e_ < 0.005:
                label, why = "noise", f"placeholder geometry: half-diagonal {e_*1000:.3g} mm, k = {k:.3g} m, mass {m:g} kg"
            elif r and r < 1 / 30:
                why = f"k = {k:.3g} m is {r:.3g} x the half-diagonal {e_:.3g} m of real geometry, mass {m:g} kg: inertia far too small for the body"
            elif not fires:
                label, why = "noise", f"k = {k:.3g} m is {r:.3g} x the link's collision half-diagonal {e_:.3g} m, but the collision covers only part of the body: the visual/welded-group geometry (or a mesh of unknown size) is larger"
            else:
                why = f"k = {k:.3g} m is {r:.3g} x the half-diagonal {e_:.3g} m of all the group's geometry, mass {m:g} kg"
        elif rule in ("inertia-exceeds-geometry", "com-outside-geometry"):
            mass_note = ""
            tiny = ("half_diagonal" in v and v["half_diagonal"] < 2 * 0.005) or ("allowed" in v and v["allowed"] < 0.005)
            if tiny:
                label, why = "noise", "placeholder geometry: " + ", ".join(f"{a} {b:.3g}" for a, b in v.items())
            elif not fires:
                label, why = "noise", ("mass lumped or geometry partial: inside the union of the collision and visual geometry of the welded group (or a mesh of unknown size), or a dummy mass <= 1 g; " +
                                       ", ".join(f"{a} {b:.3g}" for a, b in v.items()))
            else:
                why = "outside all the group's known geometry even with a 2x margin: " + ", ".join(f"{a} {b:.3g}" for a, b in v.items())
        elif rule == "inertial-missing":
            if not fires and e["format"] == "urdf":
                label, why = "noise", f"URDF link with {int(g(v,'collisions'))} collision(s) welded to links that carry mass (mass lumped onto the neighbour), or zero-size collisions"
            elif not fires:
                label, why = "noise", "zero-size or placeholder collision geometry on a frame link"
            else:
                why = (f"{int(g(v,'collisions'))} collision(s), no <inertial>: " +
                       ("SDF gives it 1 kg and I = diag(1,1,1) kg·m²" if e["format"] == "sdf" else "the welded group has no mass"))
        elif rule == "zero-inertia-about-joint-axis":
            why = f"mass {g(v,'mass'):g} kg turning on a joint with moment {g(v,'moment_about_axis'):g} kg·m² about its axis: singular"
        elif rule == "products-sign-suspect":
            why = f"invalid as written, valid with products negated (ixy {g(v,'ixy'):g}, ixz {g(v,'ixz'):g}, iyz {g(v,'iyz'):g})"
        else:
            why = f["message"][:120]
        print("\t".join([e["path"], rule, link, label, why.replace("\t", " ")]))
