// The two change-notification mechanisms of hot reload (file_events.hpp): polling, and
// inotify on the folders that hold the watched files. A folder, not the file, because an
// editor that saves by writing a new file and renaming it over the old one replaces the
// inode a file watch would follow.
#include "file_events.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <stdexcept>

#if defined(__linux__)
#include <sys/inotify.h>
#include <unistd.h>
#define PRISM_HAVE_INOTIFY 1
#endif

namespace prism::render::detail {
namespace {

class PollingEvents final : public FileEvents {
  public:
    WatchMechanism mechanism() const override { return WatchMechanism::Polling; }
    void add(const std::string&) override {}
    std::optional<std::set<std::string>> touched() override { return std::nullopt; }
};

#ifdef PRISM_HAVE_INOTIFY
// Saved (closed after writing), renamed in or out, created, deleted, or its times set.
constexpr std::uint32_t kEvents =
    IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE | IN_ATTRIB | IN_DELETE_SELF | IN_MOVE_SELF;

class InotifyEvents final : public FileEvents {
  public:
    explicit InotifyEvents(int fd) : fd_(fd) {}
    ~InotifyEvents() override { ::close(fd_); }
    InotifyEvents(const InotifyEvents&) = delete;
    InotifyEvents& operator=(const InotifyEvents&) = delete;

    WatchMechanism mechanism() const override { return WatchMechanism::Inotify; }

    void add(const std::string& path) override {
        if (!files_.insert(path).second) return;
        const std::string dir = std::filesystem::path(path).parent_path().string();
        if (dirs_.count(dir)) return;
        const int wd = ::inotify_add_watch(fd_, dir.c_str(), kEvents);
        if (wd < 0) {
            unwatched_.insert(path);  // no folder (yet) to watch: looked at every check
            return;
        }
        dirs_[dir] = wd;
        dirOf_[wd] = dir;
    }

    std::optional<std::set<std::string>> touched() override {
        std::set<std::string> out = unwatched_;
        alignas(inotify_event) char buffer[16384];
        for (;;) {
            const auto n = ::read(fd_, buffer, sizeof buffer);
            if (n <= 0) break;  // EAGAIN: the queue is empty
            for (auto at = buffer; at < buffer + n;) {
                const auto* e = reinterpret_cast<const inotify_event*>(at);
                at += sizeof(inotify_event) + e->len;
                if (!note(*e, out)) return std::nullopt;
            }
        }
        return out;
    }

  private:
    // Adds the file `e` names to `out`; false when every file must be looked at.
    bool note(const inotify_event& e, std::set<std::string>& out) {
        if (e.mask & IN_Q_OVERFLOW) return false;  // events were lost
        const auto dir = dirOf_.find(e.wd);
        if (dir == dirOf_.end()) return true;
        if (e.mask & (IN_IGNORED | IN_DELETE_SELF | IN_MOVE_SELF)) {  // the folder went away
            const std::string gone = dir->second;
            for (const auto& f : files_)
                if (std::filesystem::path(f).parent_path() == gone) unwatched_.insert(f);
            ::inotify_rm_watch(fd_, e.wd);
            dirs_.erase(gone);
            dirOf_.erase(dir);
            return false;
        }
        if (e.len == 0) return true;
        const std::string path = dir->second + "/" + e.name;
        if (files_.count(path)) out.insert(path);
        return true;
    }

    int fd_;
    std::set<std::string> files_;
    std::set<std::string> unwatched_;
    std::map<std::string, int> dirs_;
    std::map<int, std::string> dirOf_;
};
#endif

}  // namespace

std::unique_ptr<FileEvents> makeFileEvents(WatchMechanism wanted) {
    if (wanted == WatchMechanism::Polling) return std::make_unique<PollingEvents>();
#ifdef PRISM_HAVE_INOTIFY
    const int fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd >= 0) return std::make_unique<InotifyEvents>(fd);
    if (wanted == WatchMechanism::Inotify)
        throw std::runtime_error(std::string("prism: hot reload cannot start inotify: ") + std::strerror(errno) +
                                 " (raise fs.inotify.max_user_instances, or use WatchMechanism::Polling)");
#else
    if (wanted == WatchMechanism::Inotify)
        throw std::runtime_error("prism: hot reload: this platform has no inotify; use WatchMechanism::Polling");
#endif
    return std::make_unique<PollingEvents>();
}

}  // namespace prism::render::detail
