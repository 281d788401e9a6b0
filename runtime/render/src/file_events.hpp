// Which watched files a hot-reload check should look at: every one (polling), or only
// those the kernel reported touched since the last check (inotify, Linux). Either way the
// watcher then compares size, time and content itself, so a report only narrows the look
// and never decides alone that a file changed. Private to prism_render (ShaderWatcher).
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>

#include "prism/render/shader_watcher.hpp"

namespace prism::render::detail {

class FileEvents {
  public:
    virtual ~FileEvents() = default;
    // Inotify or Polling: the mechanism chosen at construction.
    virtual WatchMechanism mechanism() const = 0;
    // Starts reporting `path` (absolute, normalised), which need not exist yet.
    virtual void add(const std::string& path) = 0;
    // The added paths touched since the last call; nullopt: look at every file.
    virtual std::optional<std::set<std::string>> touched() = 0;
};

// Automatic: inotify where the platform has it (and has an instance left), else polling.
// Inotify where it cannot start throws std::runtime_error saying so.
std::unique_ptr<FileEvents> makeFileEvents(WatchMechanism wanted);

}  // namespace prism::render::detail
