// The URDF reader's call of urdfdom (reader.h): urdf::parseURDF, with the messages urdfdom logs
// through console_bridge captured for the thread that reads.
#include "io/urdf/reader.h"

namespace massprops::internal::urdf_reader {

// ------------------------------------------------------------------ console_bridge

// urdfdom reports what it cannot read through console_bridge, which keeps ONE output handler and
// ONE log level for the whole process (console_bridge 1.0.1, src/console.cpp: a function-local
// static DefaultOutputHandler; log() filters by the level, then calls the handler while holding
// that object's mutex). massprops installs one handler of its own, once, in front of the one it
// finds; it captures what a thread logs while that thread is inside ParseWithUrdfdom (a
// thread_local list) and forwards everything else to the handler it found, so several threads
// read URDF at once and a library user's logging still arrives. Nothing else in urdf::parseURDF
// is shared between threads (urdfdom 3.0.1, urdf_parser/src/{model,link,joint,pose}.cpp: no
// static or global state, numbers through urdf::strToDouble of urdf_model/utils.h, a local
// stringstream imbued with std::locale::classic(); TinyXML 2.6.2, tinyxml.h: a local
// TiXmlDocument, its only mutable static, condenseWhiteSpace, written by SetCondenseWhiteSpace
// alone, which neither urdfdom nor massprops calls).
namespace {

thread_local std::vector<std::string>* t_urdfdom_errors = nullptr;

class UrdfdomRouter final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* file,
           int line) override {
    if (t_urdfdom_errors != nullptr) {  // a massprops read: keep its errors, print nothing
      if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) t_urdfdom_errors->push_back(text);
      return;
    }
    console_bridge::OutputHandler* next = next_.load();
    if (next != nullptr && level >= forward_from_.load()) next->log(text, level, file, line);
  }
  std::atomic<console_bridge::OutputHandler*> next_{nullptr};
  // Messages of other code below this level are dropped: CONSOLE_BRIDGE_LOG_NONE while a read has
  // lowered the process's level from NONE to ERROR (the caller asked for no output).
  std::atomic<console_bridge::LogLevel> forward_from_{console_bridge::CONSOLE_BRIDGE_LOG_DEBUG};
};

// Never destroyed: console_bridge may call it until the process ends.
UrdfdomRouter& Router() {
  static UrdfdomRouter* const router = new UrdfdomRouter;
  return *router;
}

// Readers that find the router in front and the level at ERROR or below parse at once, together
// (shared); a reader that must change the handler or the level for its read does it alone
// (exclusive), and puts both back afterwards.
std::shared_mutex& UrdfdomSetupMutex() {
  static std::shared_mutex mutex;
  return mutex;
}

bool RouterReady() {
  return console_bridge::getOutputHandler() == &Router() &&
         console_bridge::getLogLevel() <= console_bridge::CONSOLE_BRIDGE_LOG_ERROR;
}

urdf::ModelInterfaceSharedPtr ParseCapturing(const std::string& xml,
                                             std::vector<std::string>* errors) {
  struct Scope {
    explicit Scope(std::vector<std::string>* e) { t_urdfdom_errors = e; }
    ~Scope() { t_urdfdom_errors = nullptr; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
  } scope(errors);
  try {
    return urdf::parseURDF(xml);
  } catch (const std::exception& e) {  // urdfdom does not throw today; be safe if it does
    errors->push_back(e.what());
    return nullptr;
  }
}

// The caller replaced massprops' handler, or set the level to NONE: one read with the router in
// front and the level at ERROR, then the caller's handler and level again.
urdf::ModelInterfaceSharedPtr ParseAlone(const std::string& xml, std::vector<std::string>* errors) {
  const std::unique_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
  if (RouterReady()) return ParseCapturing(xml, errors);
  UrdfdomRouter& router = Router();
  const bool swap_handler = console_bridge::getOutputHandler() != &router;
  const console_bridge::LogLevel level = console_bridge::getLogLevel();
  const bool lower_level = level > console_bridge::CONSOLE_BRIDGE_LOG_ERROR;
  if (swap_handler) {
    router.next_ = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(&router);
  }
  if (lower_level) {
    router.forward_from_ = level;
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
  }
  struct Restore {
    bool handler_swapped;
    bool level_lowered;
    console_bridge::LogLevel level_was;
    ~Restore() {
      if (level_lowered) {
        console_bridge::setLogLevel(level_was);
        Router().forward_from_ = console_bridge::CONSOLE_BRIDGE_LOG_DEBUG;
      }
      if (handler_swapped) console_bridge::restorePreviousOutputHandler();
    }
  } restore{swap_handler, lower_level, level};
  return ParseCapturing(xml, errors);
}

}  // namespace

urdf::ModelInterfaceSharedPtr ParseWithUrdfdom(const std::string& xml,
                                               std::vector<std::string>* errors) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    const std::unique_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
    Router().next_ = console_bridge::getOutputHandler();
    console_bridge::useOutputHandler(&Router());
  });
  errors->clear();
  {
    const std::shared_lock<std::shared_mutex> lock(UrdfdomSetupMutex());
    if (RouterReady()) return ParseCapturing(xml, errors);
  }
  return ParseAlone(xml, errors);
}

// urdfdom's links hold their children by shared_ptr (parents by weak_ptr). A file whose joints
// form a loop beside the root (which urdfdom accepts) makes a cycle of shared_ptrs that is never
// freed: clear the child lists so that the whole model goes with its last owner.
void ReleaseUrdfdomModel(urdf::ModelInterfaceSharedPtr model) {
  if (!model) return;
  for (auto& [name, link] : model->links_) {
    if (!link) continue;
    link->child_links.clear();
    link->child_joints.clear();
  }
}

}  // namespace massprops::internal::urdf_reader
