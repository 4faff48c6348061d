// FileWatcher: inotify on the directories of the watched files (see runtime/FileWatcher.h for why not on
// the files themselves).
#include <runtime/FileWatcher.h>

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>

namespace runtime {

namespace {

// What a save looks like from the directory: an in-place write ends with CLOSE_WRITE (MODIFY for writers
// that keep the file open), a replace with MOVED_TO or CREATE; a delete-then-write also passes DELETE.
constexpr uint32_t kWatchMask =
    IN_CLOSE_WRITE | IN_MODIFY | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_ATTRIB | IN_MOVED_FROM;

std::string absolutePath(const std::string& path) {
    std::error_code ignored;
    std::filesystem::path absolute = std::filesystem::absolute(path, ignored);
    return absolute.lexically_normal().string();
}

}  // namespace

FileWatcher::FileWatcher() {
    mFd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
}

FileWatcher::~FileWatcher() {
    if (mFd >= 0) close(mFd);
}

void FileWatcher::setFiles(const std::vector<std::string>& paths) {
    mFiles.clear();
    std::set<std::string> directories;
    for (const std::string& path : paths) {
        const std::string absolute = absolutePath(path);
        mFiles.insert(absolute);
        directories.insert(std::filesystem::path(absolute).parent_path().string());
    }
    if (mFd < 0) return;
    // Drop watches on directories no longer needed; add the new ones. inotify returns the same descriptor
    // for a directory watched twice, so re-adding is harmless.
    std::vector<std::pair<int, std::string>> kept;
    for (const auto& [wd, directory] : mWatches) {
        if (directories.count(directory) != 0) {
            kept.emplace_back(wd, directory);
        } else {
            inotify_rm_watch(mFd, wd);
        }
    }
    mWatches = std::move(kept);
    for (const std::string& directory : directories) {
        const bool watched = std::any_of(mWatches.begin(), mWatches.end(),
                                         [&](const auto& watch) { return watch.second == directory; });
        if (watched) continue;
        const int wd = inotify_add_watch(mFd, directory.c_str(), kWatchMask);
        if (wd >= 0) mWatches.emplace_back(wd, directory);
    }
}

bool FileWatcher::drain(std::set<std::string>& changed) {
    bool completed = false;
    alignas(inotify_event) char buffer[16 * 1024];
    for (;;) {
        const ssize_t length = read(mFd, buffer, sizeof buffer);
        if (length <= 0) return completed;  // EAGAIN: nothing more now
        for (ssize_t offset = 0; offset < length;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + offset);
            offset += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            if (event->len == 0) continue;  // an event on the directory itself
            auto watch = std::find_if(mWatches.begin(), mWatches.end(),
                                      [&](const auto& w) { return w.first == event->wd; });
            if (watch == mWatches.end()) continue;
            const std::string path = (std::filesystem::path(watch->second) / event->name).string();
            if (mFiles.count(path) == 0) continue;
            changed.insert(path);
            completed = completed || (event->mask & (IN_CLOSE_WRITE | IN_MOVED_TO)) != 0;
        }
    }
}

std::vector<std::string> FileWatcher::waitForChange(std::chrono::milliseconds timeout,
                                                    std::chrono::milliseconds debounce) {
    if (mFd < 0) return {};
    using Clock = std::chrono::steady_clock;
    std::set<std::string> changed;
    const Clock::time_point deadline = Clock::now() + timeout;
    // Phase 1: wait for the first event on a watched file (events on other files in the directories,
    // such as an editor's swap files, are read and ignored).
    bool completed = false;
    for (;;) {
        completed = drain(changed) || completed;
        if (!changed.empty()) break;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
        if (left.count() <= 0) return {};
        pollfd descriptor{mFd, POLLIN, 0};
        const int ready = poll(&descriptor, 1, static_cast<int>(left.count()));
        if (ready < 0 && errno != EINTR) return {};
    }
    // Phase 2: debounce. An editor's save is several events within a few milliseconds; reloading on
    // the first would read a half-written file. Once a watched file was closed after writing or renamed
    // into place its content is complete, and only the rest of the burst (attributes, other files of a
    // multi-file save) needs a short quiet interval: that keeps save-to-frame latency low.
    for (;;) {
        const auto quiet = completed ? std::min(debounce, kSettleAfterCompletedWrite) : debounce;
        pollfd descriptor{mFd, POLLIN, 0};
        const int ready = poll(&descriptor, 1, static_cast<int>(quiet.count()));
        if (ready == 0) break;
        if (ready < 0 && errno != EINTR) break;
        completed = drain(changed) || completed;
    }
    return {changed.begin(), changed.end()};
}

}  // namespace runtime
