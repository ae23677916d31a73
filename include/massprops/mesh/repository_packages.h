#pragma once
/// @file
/// The ROS packages of the repository a robot description sits in, found without any search
/// path, as a workspace tool would find them: the folders whose package.xml names them.
///
/// The repository of a folder is its nearest ancestor (itself included) that holds `.git` (a
/// folder, or the file of a worktree or submodule). Outside any repository (a downloaded
/// archive, a copied tree) the crawl covers the folder that holds the description's package
/// (the parent of the nearest ancestor with a package.xml: a repository's top or a workspace's
/// src/), or, with no package.xml above, the description's own folder: never the whole file
/// system, where it would be slow and find unrelated copies of a package.
/// The crawl goes nearest first: the folder's own subtree, then its parent's (the part not yet
/// seen), and so on up to that root, so the package nearest the description wins. It skips
/// hidden folders, build/, install/ and log/ (a colcon workspace's outputs), folders holding
/// CATKIN_IGNORE, COLCON_IGNORE or AMENT_IGNORE, symbolic links, and, outside a repository,
/// repositories (folders holding `.git`). As in catkin and
/// colcon, a folder with a package.xml is a package and is not searched further. At most
/// `max_folders` folders are listed per RepositoryPackages (one per run): the packages under
/// each folder on the way up are remembered, so a folder crawled for one description is not
/// listed again for the next.

#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace massprops {

/// The <name> of `folder`/package.xml (surrounding white space trimmed), or "" when there is
/// no such file, it is not XML, or it has no <package><name>. Never throws.
std::string PackageXmlName(const std::string& folder);

/// The repository root of `folder`: the nearest of it and its ancestors that holds an entry
/// named `.git`, else the filesystem root. `folder` is made absolute (against the working
/// directory) and lexically normal first. Never throws. Cost: one stat per folder upward.
std::string FindRepositoryRoot(const std::string& folder);

/// The folder whose subtree RepositoryPackages::Find crawls for a description in `folder`:
/// FindRepositoryRoot(folder) when that holds `.git`; else the parent of the nearest of `folder`
/// and its ancestors that holds a package.xml; else `folder` (absolute, lexically normal).
/// Never throws.
std::string FindPackageSearchRoot(const std::string& folder);

/// The nearest of `folder` and its ancestors, up to FindRepositoryRoot(folder) included, whose
/// name is `name` and that holds no package.xml naming another package (CAD exports often ship
/// a package folder without package.xml). nullopt when there is none. Never throws.
std::optional<std::string> FindAncestorNamed(const std::string& folder, const std::string& name);

/// The default bound of a crawl: folders listed per run.
inline constexpr int kDefaultMaxCrawlFolders = 50000;

/// Packages found by crawling descriptions' repositories (see the file comment), remembered for
/// the run. Thread-safe.
class RepositoryPackages {
 public:
  explicit RepositoryPackages(int max_folders = kDefaultMaxCrawlFolders)
      : max_folders_(max_folders) {}

  /// The folder of the package named `name` (its package.xml's <name>) nearest to `folder`
  /// under FindPackageSearchRoot(folder): found in the subtree of the nearest ancestor that has
  /// one; among several at that level, the shallowest, then the first by path. nullopt when there
  /// is none, or the crawl stopped at max_folders before finding one (truncated() says so).
  /// Never throws. Cost: the first call lists up to max_folders folders (reading each
  /// package.xml met); later calls reuse what was crawled.
  std::optional<std::string> Find(const std::string& folder, const std::string& name);

  /// FindPackageSearchRoot(folder), remembered per folder.
  std::string SearchRoot(const std::string& folder);

  /// FindAncestorNamed(folder, name), remembered per (folder, name).
  std::optional<std::string> FindAncestor(const std::string& folder, const std::string& name);

  /// Folders listed so far (the budget used).
  int folders_listed() const;
  /// Whether some crawl stopped at max_folders.
  bool truncated() const;
  int max_folders() const { return max_folders_; }

 private:
  struct Package {
    std::string name;
    std::string folder;
    int depth;  // below the subtree's top
  };
  // The packages of one folder's subtree, as far as it was crawled.
  using Subtree = std::vector<Package>;
  // The packages under `top` (crawled once; a folder below crawled before is not listed again).
  const Subtree& CrawlLocked(const std::string& top, bool other_repositories);

  const int max_folders_;
  mutable std::mutex mutex_;
  int folders_listed_ = 0;
  bool truncated_ = false;
  std::unordered_map<std::string, Subtree> subtrees_;   // by folder, for the folders upward
  std::unordered_map<std::string, std::string> roots_;  // FindPackageSearchRoot, by folder
  std::unordered_map<std::string, std::optional<std::string>> ancestors_;  // by folder + name
};

}  // namespace massprops
