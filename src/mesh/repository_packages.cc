#include "massprops/mesh/repository_packages.h"

#include <tinyxml2.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <utility>

namespace massprops {
namespace fs = std::filesystem;

namespace {

// `folder` made absolute and lexically normal, without a trailing separator; `folder` itself
// when the working directory cannot be known.
fs::path Normal(const std::string& folder) {
  std::error_code ec;
  fs::path path = fs::absolute(fs::path(folder.empty() ? "." : folder), ec);
  if (ec) path = fs::path(folder);
  path = path.lexically_normal();
  if (!path.has_filename() && path.has_relative_path()) path = path.parent_path();
  return path;
}

bool HasEntry(const fs::path& path) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(path, ec));
}

// `start` and each of its ancestors up to `root` (included), nearest first.
std::vector<fs::path> ChainUpTo(const fs::path& start, const fs::path& root) {
  std::vector<fs::path> chain;
  fs::path current = start;
  while (true) {
    chain.push_back(current);
    if (current == root) break;
    const fs::path parent = current.parent_path();
    if (parent == current || parent.empty()) break;
    current = parent;
  }
  return chain;
}

bool IsSkippedName(const std::string& name) {
  return name.empty() || name[0] == '.' || name == "build" || name == "install" || name == "log";
}

}  // namespace

std::string PackageXmlName(const std::string& folder) {
  const fs::path manifest = fs::path(folder) / "package.xml";
  std::error_code ec;
  if (!fs::is_regular_file(manifest, ec)) return "";
  tinyxml2::XMLDocument document;
  if (document.LoadFile(manifest.string().c_str()) != tinyxml2::XML_SUCCESS) return "";
  const tinyxml2::XMLElement* package = document.FirstChildElement("package");
  const tinyxml2::XMLElement* name = package ? package->FirstChildElement("name") : nullptr;
  if (name == nullptr || name->GetText() == nullptr) return "";
  const std::string text = name->GetText();
  const auto first = text.find_first_not_of(" \t\r\n");
  const auto last = text.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

std::string FindRepositoryRoot(const std::string& folder) {
  const fs::path start = Normal(folder);
  fs::path current = start;
  while (true) {
    if (HasEntry(current / ".git")) return current.string();
    const fs::path parent = current.parent_path();
    if (parent == current || parent.empty()) return current.string();
    current = parent;
  }
}

std::string FindPackageSearchRoot(const std::string& folder) {
  const fs::path start = Normal(folder);
  const std::string repository = FindRepositoryRoot(start.string());
  if (HasEntry(fs::path(repository) / ".git")) return repository;
  for (const fs::path& ancestor : ChainUpTo(start, fs::path(repository))) {
    std::error_code ec;
    if (fs::is_regular_file(ancestor / "package.xml", ec)) {
      const fs::path parent = ancestor.parent_path();
      return (parent.empty() ? ancestor : parent).string();
    }
  }
  return start.string();
}

std::optional<std::string> FindAncestorNamed(const std::string& folder, const std::string& name) {
  if (name.empty()) return std::nullopt;
  const fs::path start = Normal(folder);
  // No folder of that name on the way up: nothing to look at on the disk.
  bool named = false;
  for (const fs::path& part : start) named = named || part == name;
  if (!named) return std::nullopt;
  for (const fs::path& ancestor : ChainUpTo(start, fs::path(FindRepositoryRoot(start.string())))) {
    if (ancestor.filename() != name) continue;
    const std::string named = PackageXmlName(ancestor.string());
    if (named.empty() || named == name) return ancestor.string();  // package.xml wins
  }
  return std::nullopt;
}

const RepositoryPackages::Subtree& RepositoryPackages::CrawlLocked(const std::string& top,
                                                                   bool other_repositories) {
  if (auto found = subtrees_.find(top); found != subtrees_.end()) return found->second;
  Subtree packages;
  std::deque<std::pair<fs::path, int>> queue{{fs::path(top), 0}};
  while (!queue.empty()) {
    auto [folder, depth] = std::move(queue.front());
    queue.pop_front();
    // A folder crawled before (the one below on the way up): what was found there, unlisted.
    if (auto seen = subtrees_.find(folder.string()); depth > 0 && seen != subtrees_.end()) {
      for (const Package& p : seen->second) packages.push_back({p.name, p.folder, p.depth + depth});
      continue;
    }
    if (folders_listed_ >= max_folders_) {
      truncated_ = true;
      break;
    }
    ++folders_listed_;
    bool has_manifest = false, ignored = false, repository = false;
    std::vector<std::string> children;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      std::error_code entry_ec;
      if (name == "package.xml") {
        has_manifest = true;
      } else if (name == "CATKIN_IGNORE" || name == "COLCON_IGNORE" || name == "AMENT_IGNORE") {
        ignored = true;
      } else if (name == ".git") {
        repository = true;
      } else if (!IsSkippedName(name) && !it->is_symlink(entry_ec) && it->is_directory(entry_ec)) {
        children.push_back(name);
      }
    }
    if (ignored || (repository && depth > 0 && !other_repositories)) continue;
    if (has_manifest) {  // a package: its subfolders are not searched (catkin, colcon)
      const std::string name = PackageXmlName(folder.string());
      if (!name.empty()) packages.push_back({name, folder.string(), depth});
      continue;
    }
    std::sort(children.begin(), children.end());
    for (const std::string& name : children) queue.emplace_back(folder / name, depth + 1);
  }
  return subtrees_.emplace(top, std::move(packages)).first->second;
}

std::optional<std::string> RepositoryPackages::Find(const std::string& folder,
                                                    const std::string& name) {
  if (name.empty()) return std::nullopt;
  const fs::path start = Normal(folder);
  std::lock_guard<std::mutex> lock(mutex_);
  auto root = roots_.find(start.string());
  if (root == roots_.end()) {
    root = roots_.emplace(start.string(), FindPackageSearchRoot(start.string())).first;
  }
  const bool in_repository = HasEntry(fs::path(root->second) / ".git");
  for (const fs::path& level : ChainUpTo(start, fs::path(root->second))) {
    const Subtree& packages = CrawlLocked(level.string(), in_repository);
    const Package* best = nullptr;
    for (const Package& p : packages) {
      if (p.name != name) continue;
      if (best == nullptr || p.depth < best->depth ||
          (p.depth == best->depth && p.folder < best->folder)) {
        best = &p;
      }
    }
    if (best != nullptr) return best->folder;
  }
  return std::nullopt;
}

std::string RepositoryPackages::SearchRoot(const std::string& folder) {
  const std::string start = Normal(folder).string();
  std::lock_guard<std::mutex> lock(mutex_);
  auto root = roots_.find(start);
  if (root == roots_.end()) root = roots_.emplace(start, FindPackageSearchRoot(start)).first;
  return root->second;
}

std::optional<std::string> RepositoryPackages::FindAncestor(const std::string& folder,
                                                            const std::string& name) {
  const std::string key = Normal(folder).string() + '\n' + name;
  std::lock_guard<std::mutex> lock(mutex_);
  auto found = ancestors_.find(key);
  if (found == ancestors_.end()) {
    found = ancestors_.emplace(key, FindAncestorNamed(folder, name)).first;
  }
  return found->second;
}

int RepositoryPackages::folders_listed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return folders_listed_;
}

bool RepositoryPackages::truncated() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return truncated_;
}

}  // namespace massprops
