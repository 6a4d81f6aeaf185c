// Which of Mitsuba 3's plugins twinray implements, and why each other one is refused. One table
// for the whole loader: a scene is checked against it before anything is built, so a scene that
// asks for an unsupported plugin fails on the first such plugin in document order with
// "not supported by twinray: <plugin>" and the reason.
#pragma once

#include <string>

#include "scenes/properties.h"
#include "scenes/scene.h"

namespace tr {

enum class PluginSupport {
  Supported,
  OutOfScope,     // twinray models RGB light transport in vacuum: no polarization, media...
  Unimplemented,  // a Mitsuba plugin that twinray does not implement
  Unknown,        // not a Mitsuba 3 plugin of this kind at all (a typo?)
};

struct PluginStatus {
  PluginSupport support;
  const char* reason;  // why it is not supported; empty when supported
};

PluginStatus plugin_status(const std::string& tag, const std::string& type);

// A scene refused because it asks for a plugin twinray does not implement.
class UnsupportedPluginError : public SceneError {
 public:
  UnsupportedPluginError(const std::string& message, std::string tag, std::string type,
                         PluginSupport support)
      : SceneError(message), tag(std::move(tag)), type(std::move(type)), support(support) {}
  std::string tag, type;
  PluginSupport support;
};

// Throws UnsupportedPluginError for the first unsupported plugin of the tree, in document order.
void check_plugins(const Node& root);

}  // namespace tr
