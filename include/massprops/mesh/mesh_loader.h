#pragma once
/// @file
/// Meshes referenced by URDF/SDF geometries: resolving their URIs, loading them (STL ascii and
/// binary, OBJ, DAE through assimp), and the unit-density mass properties of a link's geometry in
/// the link frame — the entry points for checks and reports that compare declared inertias with
/// the geometry (CalcGeometryMassProperties, CalcLinkGeometryInertia).
///
/// Failures (a file not found, unreadable, empty, an unsupported geometry) are values: a
/// function returns false/nullopt and sets *error to a message naming the URI and the reason.
/// Nothing here throws for bad input.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "massprops/core/rotational_inertia.h"
#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/repository_packages.h"
#include "massprops/model/model.h"

namespace massprops {

class MeshCache;

/// Where mesh URIs are looked up, and how meshes are modelled.
struct MeshResolveOptions {
  /// `package://NAME/rest` is looked up, in this order, in: these folders (from --package-path
  /// or a configuration's package-paths; in each folder P the package is P/NAME, or P itself or
  /// a child folder of P whose package.xml has <name>NAME</name>); the package named NAME in
  /// the description's repository (RepositoryPackages, when search_repository); an ancestor
  /// folder of the description named NAME without a package.xml naming another package
  /// (FindAncestorNamed, when search_repository); then, when use_environment, the folders of
  /// ROS_PACKAGE_PATH and DIR/share for each DIR of AMENT_PREFIX_PATH, as in the first step.
  /// The first package that holds the file wins. `package:///rest` (no name) is the file `rest`
  /// beside the description, as onshape-to-robot writes it.
  std::vector<std::string> package_paths;
  /// `model://NAME/rest`: these folders first, then SDF_PATH, GZ_SIM_RESOURCE_PATH,
  /// IGN_GAZEBO_RESOURCE_PATH and GAZEBO_MODEL_PATH (when use_environment); the model is P/NAME.
  std::vector<std::string> model_paths;
  /// Read the environment variables above.
  bool use_environment = true;
  /// Look for packages in the description's repository and among its ancestor folders.
  bool search_repository = true;
  /// The model file that references the meshes: relative paths (and `file://` relative paths)
  /// are relative to its folder (to the current directory when empty or "-"). A geometry whose
  /// location names another file (a model included by an SDF world) is resolved relative to
  /// that file instead (CalcGeometryMassProperties).
  std::string model_file;
  /// How open or non-manifold meshes are modelled (density is ignored: results are per unit
  /// density, or scaled to a given mass).
  MeshInertiaOptions inertia;
  /// Loads each file once and reuses it (and its mass properties per scale); may be null.
  /// The cache must outlive the calls that use it.
  MeshCache* cache = nullptr;
};

/// How a mesh URI was resolved (MeshResolveOptions says the order).
enum class MeshFoundBy {
  kNone,               ///< Not resolved.
  kFlag,               ///< package_paths / model_paths (--package-path, --model-path, config).
  kRepositoryPackage,  ///< A package.xml naming the package in the description's repository.
  kAncestor,           ///< An ancestor folder of the description named as the package.
  kEnvironment,        ///< ROS_PACKAGE_PATH, AMENT_PREFIX_PATH, SDF_PATH and the like.
  kBesideFile,         ///< `package:///rest`: beside the description file.
  kRelative,           ///< A relative path (or relative file://): from the description's folder.
  kAbsolute,           ///< An absolute path or file:///abs/path.
};

/// "none", "flag", "repository-package", "ancestor", "environment", "beside-file", "relative",
/// "absolute": the names JSON uses.
const char* ToString(MeshFoundBy found_by);

/// The path of the file a mesh URI names, checked to exist as a regular file; *found_by (if not
/// null) says how it was found. Returns nullopt (found_by kNone) and sets *error (if not null)
/// when the scheme is not supported (http://, ...), the package or model is not found where it
/// is looked for (the message lists where), or the file is not there. Packages in the
/// description's repository are crawled through options.cache's RepositoryPackages (once per
/// run), or a fresh one when there is no cache. Cost: a few file-system queries per search
/// path (package.xml files are read), plus the repository crawl when a package is not found
/// by the search paths (RepositoryPackages::Find).
std::optional<std::string> ResolveMeshUri(const std::string& uri, const MeshResolveOptions& options,
                                          std::string* error, MeshFoundBy* found_by = nullptr);

/// ResolveMeshUri for a mesh geometry: through options.cache when there is one, and from the
/// file that holds the geometry (geometry.location.file, e.g. a model an SDF world includes)
/// rather than options.model_file when it is known.
std::optional<std::string> ResolveGeometryMeshUri(const Geometry& geometry,
                                                  const MeshResolveOptions& options,
                                                  std::string* error,
                                                  MeshFoundBy* found_by = nullptr);

/// Loads a mesh file (format chosen by assimp from the content and extension: STL ascii or
/// binary, OBJ, DAE, ...) as one triangle mesh in the file's length unit converted to meters
/// where the format says so: the scene graph's node transforms are applied, and a DAE
/// <unit meter="..."> is honoured (assimp 5.2 puts it into the root node's transform; the DAE
/// <up_axis> is ignored: URDF and SDF take mesh coordinates as they are written). Only assimp's
/// aiProcess_Triangulate is applied, and identical vertices are joined exactly as assimp 5.2.4's
/// aiProcess_JoinIdenticalVertices joins them, at a fraction of its cost (docs/meshes.md,
/// "Vertex joining"): nothing that changes the geometry; points and lines are dropped. Assimp holds
/// coordinates as 32-bit floats, so vertices carry a relative rounding of up to 6e-8. Returns false
/// and sets *error (if not null) when the file cannot be read or parsed, or holds no triangle.
bool LoadMeshFile(const std::string& path, TriangleMesh* mesh, std::string* error);

/// SDF `<submesh>`: which part of a mesh file a geometry is (Geometry::submesh and
/// Geometry::center_submesh). An empty name is the whole file.
struct MeshSubmesh {
  std::string name;
  /// Each selected part moved so that the center of its vertices' bounding box is the mesh
  /// frame's origin, as gz-common's SubMesh::Center(0) does; before the geometry's scale.
  bool center = false;
};

/// The part of its file `geometry` selects: {geometry.submesh, geometry.center_submesh}.
MeshSubmesh SubmeshOf(const Geometry& geometry);

/// LoadMeshFile's mesh of the named part of the file at `path` (submesh.name empty: the whole
/// file, as LoadMeshFile). A part is one mesh of one node of the file's scene graph, named as
/// gz-common names its submeshes: the node's name (a DAE `<node name>`, an OBJ `o`), or for a DAE
/// node without a name that of its nearest named ancestor. Every part of that name is taken, each
/// recentred on its own bounding box when submesh.center is set (as Gazebo's renderer draws a
/// visual's submesh). STL files have no named parts here. Returns false and sets *error (which
/// names the file, the submesh and the names the file has) when LoadMeshFile fails or no part has
/// that name. Never throws. Cost: LoadMeshFile's, plus a pass over the part.
bool LoadMeshSubmesh(const std::string& path, const MeshSubmesh& submesh, TriangleMesh* mesh,
                     std::string* error);

/// When `geometry` is a mesh whose SDF `<submesh>` names no part of its file, the file itself
/// being found and read: a message for a warning that says so, names the URI, the submesh and the
/// parts there are, and that the geometry's size is unknown (the geometry rules then treat it as
/// of unknown size, never as the whole file). nullopt otherwise (no submesh, the part found, or the
/// file not found or unreadable: those are said where meshes that do not resolve are). Through
/// options.cache when set. Never throws.
std::optional<std::string> UnknownSubmeshMessage(const Geometry& geometry,
                                                 const MeshResolveOptions& options);

/// The axis-aligned bounding box of the mesh file at `path`: of the vertices LoadMeshFile would
/// give (same frame, unit and float rounding), without loading or integrating the triangles
/// where that can be avoided. STL (binary or ascii) and OBJ (vertices used by a face, line or
/// point element; `v x y z [w]` divided by w, as assimp does) are read directly, without assimp;
/// every other format (DAE: its <unit> and node transforms), and a file these direct readers do
/// not understand, goes through LoadMeshFile, so the box is always that of the full loader's mesh.
/// *direct (if not null) tells whether the direct reader was used. Returns false and sets *error
/// when LoadMeshFile would fail (no such file, cannot be parsed, no triangle, a vertex not
/// finite). Never throws. Cost: one pass over the file's bytes (direct), else LoadMeshFile's.
bool LoadMeshBounds(const std::string& path, Eigen::AlignedBox3d* box, bool* direct,
                    std::string* error);

/// The points of a mesh file that bound its convex hull (the hull rule of
/// inertia-exceeds-geometry): each distinct vertex position of LoadMeshFile's mesh once, in order
/// of first appearance, and how many vertices LoadMeshFile gives (the count findings quote).
struct MeshPoints {
  std::vector<Eigen::Vector3d> positions;
  std::int64_t loader_vertices = 0;
};

namespace internal {
class MeshStore;
}

/// MeshCache::UsePersistentCache's default bound on the cache folder: 512 MiB.
constexpr std::uint64_t kDefaultMeshCacheBytes = std::uint64_t{512} << 20;

/// Mesh files read once per run: their boxes, hull-bound points and mass properties per (file,
/// scale, options), and, with UsePersistentCache, kept between runs. A binary STL is read once,
/// directly (no assimp), for all of them and for Load (LoadMeshFile's mesh made from the same
/// read; docs/meshes.md, "Binary STL, one read"); assimp (LoadMeshFile) reads other formats, so
/// that every number is the one LoadMeshFile's mesh gives. Thread-safe: different files are read in
/// parallel.
class MeshCache {
 public:
  MeshCache();
  /// Flush().
  ~MeshCache();
  MeshCache(const MeshCache&) = delete;
  MeshCache& operator=(const MeshCache&) = delete;

  /// Keeps each mesh file's box, hull-bound points and mass properties in `folder` (created
  /// when needed; DefaultMeshCacheFolder()) between runs, keyed by the file's content hash and
  /// size, with its path, size and modification time as a shortcut that spares reading an
  /// unchanged file. Entries are written atomically; a damaged one is ignored and rewritten; the
  /// folder is trimmed to `max_bytes` (oldest entries first). Call before any other member.
  void UsePersistentCache(const std::string& folder,
                          std::uint64_t max_bytes = kDefaultMeshCacheBytes);

  /// Writes what this run derived and the persistent cache lacked, then trims it. Nothing
  /// without UsePersistentCache. Errors (a read-only folder, a full disk) are ignored.
  void Flush();

  /// Every member below takes the part of the file it is about (`submesh`, MeshSubmesh: the
  /// whole file by default); what is known of a part (its mesh, box, points and mass properties,
  /// here and in the persistent cache) is kept apart from the whole file's and from the other
  /// parts' and centerings. A part is taken from the whole file's mesh (LoadMeshSubmesh), so a
  /// file is imported once however many of its parts are used.

  /// The mesh at `path` (LoadMeshFile; LoadMeshSubmesh for a part), loading it on first use;
  /// failures are remembered too. Returns null and sets *error on failure.
  std::shared_ptr<const TriangleMesh> Load(const std::string& path, std::string* error,
                                           const MeshSubmesh& submesh = {});

  /// Unit-density mass properties of the mesh at `path` scaled by diag(scale), in the mesh
  /// frame G, computed once per (path, part, scale, options). Returns nullopt and sets *error on
  /// failure.
  std::optional<MeshMassProperties> MassProperties(const std::string& path,
                                                   const Eigen::Vector3d& scale,
                                                   const MeshInertiaOptions& options,
                                                   std::string* error,
                                                   const MeshSubmesh& submesh = {});

  /// The bounding box of the mesh at `path` (LoadMeshBounds; a part's from its mesh), read on
  /// first use; from the mesh when it was read already. Failures are remembered too. Returns
  /// nullopt and sets *error on failure.
  std::optional<Eigen::AlignedBox3d> Bounds(const std::string& path, std::string* error,
                                            const MeshSubmesh& submesh = {});

  /// The hull-bound points of the mesh at `path` (MeshPoints), read on first use. Returns
  /// null and sets *error when LoadMeshFile cannot read the file (or it has no such part).
  std::shared_ptr<const MeshPoints> Points(const std::string& path, std::string* error,
                                           const MeshSubmesh& submesh = {});

  /// The names of the parts of the mesh file at `path` that a MeshSubmesh can name
  /// (LoadMeshSubmesh), each once, in the mesh's order; empty for a file without named parts (an
  /// STL). Returns nullopt and sets *error when the file cannot be read.
  std::optional<std::vector<std::string>> SubmeshNames(const std::string& path, std::string* error);

  /// ResolveMeshUri(uri, options, error, found_by), remembered per (uri, the description's
  /// folder, the search paths, use_environment, search_repository): a model references the same
  /// mesh from many links and a package lookup lists folders and reads package.xml files.
  std::optional<std::string> Resolve(const std::string& uri, const MeshResolveOptions& options,
                                     std::string* error, MeshFoundBy* found_by = nullptr);

  /// The packages crawled in the descriptions' repositories this run.
  RepositoryPackages& packages() { return packages_; }

  /// How many times a mesh file was actually read, directly or by assimp (for tests).
  int files_loaded() const;
  /// How many files Bounds read (calls that found nothing read or cached).
  int files_bounded() const;
  /// How many files' numbers were found in the persistent cache.
  int files_from_persistent_cache() const;

 private:
  struct FileState;
  FileState& StateOf(const std::string& path, const MeshSubmesh& submesh);
  void LookUp(FileState& state, const std::string& path);
  std::shared_ptr<const TriangleMesh> LoadLocked(FileState& state, const std::string& path,
                                                 std::string* error);
  void ReadDirectLocked(FileState& state, const std::string& path);

  mutable std::mutex mutex_;  // guards files_, resolved_ and the counters
  std::map<std::string, std::unique_ptr<FileState>> files_;
  struct Resolved {
    std::optional<std::string> path;
    std::string error;
    MeshFoundBy found_by = MeshFoundBy::kNone;
  };
  std::map<std::string, Resolved> resolved_;
  RepositoryPackages packages_;
  std::shared_ptr<internal::MeshStore> store_;
  int files_loaded_ = 0;
  int files_bounded_ = 0;
  int files_from_store_ = 0;
};

/// Where `massprops` keeps mesh numbers between runs: $XDG_CACHE_HOME/massprops/meshes, or
/// ~/.cache/massprops/meshes when XDG_CACHE_HOME is unset or not an absolute path; "" when
/// neither it nor HOME is set.
std::string DefaultMeshCacheFolder();

/// Removes the cache folder `folder` and everything in it (`massprops cache clean`). Returns
/// how many files were removed (0 when there is no such folder), or -1 and sets *error.
long CleanMeshCache(const std::string& folder, std::string* error);

/// The mesh scaled by diag(scale): every vertex multiplied componentwise. A scale with an odd
/// number of negative factors mirrors the mesh, so the triangles' vertex order is reversed to
/// keep their winding. Precondition: finite scale (not checked).
TriangleMesh ScaleMesh(const TriangleMesh& mesh, const Eigen::Vector3d& scale);

/// Unit-density mass properties of one geometry, in the link frame B.
struct GeometryMassProperties {
  double volume = 0;                                    ///< = mass at density 1.
  Eigen::Vector3d p_BoGcm_B = Eigen::Vector3d::Zero();  ///< Center of mass, in the link frame.
  RotationalInertia<double> I_GGcm_B;  ///< About the center of mass, expressed in B, density 1.
  /// Axis-aligned bounding box in B: of the posed shape for primitives (CalcPrimitiveBounds), of
  /// the scaled and posed vertices for meshes.
  Eigen::AlignedBox3d box_B;
  /// Meshes only: the resolved path, how it was found, and what the mesh looked like (model
  /// used, defects).
  std::string mesh_path;
  MeshFoundBy mesh_found_by = MeshFoundBy::kNone;
  std::optional<MeshDiagnostics> mesh_diagnostics;
};

/// The unit-density volume, center and central inertia of a geometry, expressed in the link
/// frame (X_BG applied): boxes, cylinders, spheres, capsules and ellipsoids from their closed
/// forms (unit_inertia.h), meshes from their triangles (of the geometry's SDF <submesh> only when
/// it names one, LoadMeshSubmesh; scaled by the geometry's scale, see CalcMeshMassProperties for
/// open meshes). Returns nullopt and sets *error (if not null) for a mesh that cannot be resolved
/// or loaded, a <submesh> its file does not have, a geometry of type kOther, or a negative or
/// non-finite dimension. Cost: primitives about 100 flops; meshes linear in the triangles (once
/// per file and scale with a cache).
std::optional<GeometryMassProperties> CalcGeometryMassProperties(const Geometry& geometry,
                                                                 const MeshResolveOptions& options,
                                                                 std::string* error);

/// The axis-aligned bounding box, in the link frame B, of one geometry: CalcPrimitiveBounds for a
/// primitive; for a mesh, the box of its file (LoadMeshBounds, through options.cache when set; of
/// its <submesh> part only, as placed or recentred, when the geometry names one) scaled by the
/// geometry's scale and posed by X_BG. The 8 corners of the scaled box are posed,
/// not the vertices (the file's box is all that is kept per file): under a rotation that is not
/// a multiple of 90° about the axes this box is larger than that of the posed vertices (up to
/// √3 times in each direction, for a long thin mesh turned 45° about two axes); it is always an
/// upper bound, which is what the checks' "inertia too large for the geometry" verdicts need,
/// and their "too small" verdicts (a factor 30) are far above that slack.
/// CalcGeometryMassProperties gives the exact box of the posed vertices. Returns nullopt and sets
/// *error (if not null) for a mesh that cannot be resolved or read, a non-finite scale or pose, or
/// a geometry of type kOther. Never throws. Cost: primitives a few flops; a mesh one read of its
/// file per cache.
std::optional<Eigen::AlignedBox3d> CalcGeometryBounds(const Geometry& geometry,
                                                      const MeshResolveOptions& options,
                                                      std::string* error);

/// The inertia a link's geometry implies for a given mass.
struct LinkGeometryInertia {
  double mass = 0;
  double volume = 0;  ///< Sum of the geometries' volumes (overlaps counted twice).
  Eigen::Vector3d p_BoBcm_B = Eigen::Vector3d::Zero();  ///< Center of mass in the link frame.
  RotationalInertia<double> I_BBcm_B;              ///< About the center of mass, expressed in B.
  bool from_collision = true;                      ///< false when the visual geometries were used.
  Eigen::AlignedBox3d box_B;                       ///< Bounding box of the geometries used, in B.
  std::vector<GeometryMassProperties> geometries;  ///< The geometries used, in file order.
  /// Why the collision geometries were not used, when the visual ones were (empty otherwise).
  std::string note;
};

/// The center of mass and central inertia of `link` if it were a uniform body of mass `mass`
/// filling its geometry: the collision geometries if the link has any and all of them can be
/// computed, else the visual ones. Several geometries are summed as separate solids of the same
/// density (overlapping volumes count twice: a union is not computed). Returns nullopt and sets
/// *error (if not null) when the link has no geometry, a geometry of the chosen set fails (the
/// message names it), or the total volume is zero. Precondition: mass >= 0 and finite (else
/// nullopt with an error).
std::optional<LinkGeometryInertia> CalcLinkGeometryInertia(const Link& link, double mass,
                                                           const MeshResolveOptions& options,
                                                           std::string* error);

}  // namespace massprops
