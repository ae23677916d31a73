#pragma once
/// @file
/// Reading MJCF, MuJoCo's own format, into a massprops Model, with the mass properties MuJoCo
/// 2.2's compiler gives every body (docs/mjcf.md). One tinyxml2 pass per file (and per file an
/// <include> names); every element keeps its file and line.
///
/// What the Model holds: one Link per <body> in MuJoCo's body order (the <worldbody> first, as
/// the link "world"; an unnamed body is "(body N)" with N its MuJoCo body id); one Joint per
/// body other than the world, from its parent to it, whose type says how it moves: none of its
/// own <joint>s is kFixed (a body without joints is welded to its parent), one hinge kRevolute,
/// slide kPrismatic, ball kBall, free or <freejoint> kFloating, several kOther ("hinge+slide").
/// Each Link's Inertial is what the compiler makes of the body: the <inertial> as written
/// (diaginertia with its orientation; fullinertia in the body axes), or, under
/// inertiafromgeom="true" or "auto" without an <inertial>, the sum of its geoms in the inertia
/// group range (each geom's mass from its mass or density, sizes and fromto as MuJoCo reads
/// them, <default> classes applied), then boundmass, boundinertia, balanceinertia and
/// settotalmass. A Link's geometries are its geoms (contype and conaffinity both 0: a visual).

#include <string>

#include "massprops/model/model.h"

namespace massprops {

/// How the reader computes the mass properties of mesh geoms.
struct MjcfReadOptions {
  /// false (the default): the physically exact solid of each mesh (mesh_inertia.h).
  /// true (`--target mujoco`): what MuJoCo 2.2 computes, the legacy method unless the file sets
  /// <compiler exactmeshinertia="true">: every pyramid volume counted positive and the mesh
  /// replaced by the box of the same principal moments (its volume, so its mass, differs from
  /// the mesh's; docs/mjcf.md gives how much on real models).
  bool mujoco_mesh_inertia = false;
  /// <include>s nested deeper than this are a ReadError.
  int max_include_depth = 32;
};

/// Reads the MJCF text `xml` named `file_name` (used in SourceLocations and as the folder of
/// relative <include> and mesh paths). Errors (a malformed file, a number that cannot be read, an
/// unknown default class or mesh, a compiler setting MuJoCo refuses, coordinate="global") are
/// ReadErrors with file:line, and no model is returned. A body whose geom-derived inertia cannot
/// be computed (a mesh that cannot be read or that MuJoCo refuses, geoms of zero total mass)
/// gets Link::inertial_unreadable and an "inertial-unreadable" finding; the rest is read.
/// Never throws for bad input. Cost: linear in the size of the files, plus the meshes.
ReadResult ReadMjcfString(const std::string& xml, const std::string& file_name,
                          const MjcfReadOptions& options = {});

}  // namespace massprops
