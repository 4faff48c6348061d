// FileWatcher: tells hot reload that one of a set of files was saved. Watches the files' *directories*
// with inotify, not the files: editors (vim, VS Code, Emacs) save by writing a temporary file and renaming
// it over the original, so a watch on the file's inode would see one event and then go silent. Events
// come in bursts (truncate, write, close, rename, attrib); waitForChange() reports a burst once, after
// the directories have been quiet for the debounce interval.
//
// Linux only (inotify). No GL here: the watcher is testable without a context.
#pragma once

#include <chrono>
#include <set>
#include <string>
#include <vector>

namespace runtime {

class FileWatcher {
public:
    FileWatcher();
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // False if inotify could not be initialised (then nothing is ever reported).
    bool valid() const { return mFd >= 0; }

    // Replaces the watched set. Paths are made absolute; their directories are watched (once each).
    // Call again after every reload: an edit may add or remove includes.
    void setFiles(const std::vector<std::string>& paths);
    const std::set<std::string>& files() const { return mFiles; }

    // Waits up to `timeout` for an event on a watched file; once one came, keeps reading until `debounce`
    // (kSettleAfterCompletedWrite once a write completed) passes without another, and returns the watched
    // files that changed (absolute paths). Empty if the timeout passed first. A zero timeout polls.
    std::vector<std::string> waitForChange(
        std::chrono::milliseconds timeout,
        std::chrono::milliseconds debounce = std::chrono::milliseconds(50));

    // The inotify descriptor, for callers that multiplex it with poll()/select().
    int fd() const { return mFd; }

private:
    // Reads the events available now; adds watched files they name to `changed`. True if one of them
    // completed a write (IN_CLOSE_WRITE or IN_MOVED_TO on a watched file).
    bool drain(std::set<std::string>& changed);

    // The quiet interval after a completed write, instead of the full debounce.
    static constexpr std::chrono::milliseconds kSettleAfterCompletedWrite{10};

    int mFd = -1;
    std::set<std::string> mFiles;                       // absolute paths
    std::vector<std::pair<int, std::string>> mWatches;  // (watch descriptor, directory)
};

}  // namespace runtime
