// CompileWorkers: see CompileWorkers.h and docs/compile-workers.md.
#include <fx/CompileWorkers.h>

#include "CompileProtocol.h"
#include "StageCompile.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <thread>

namespace fx {

namespace {

constexpr const char* kWorkerName = "shadowfx-compile-worker";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

bool isExecutable(const std::string& path) {
    std::error_code ec;
    return !path.empty() && std::filesystem::is_regular_file(path, ec) && access(path.c_str(), X_OK) == 0;
}

struct Worker {
    pid_t pid = -1;
    int fd = -1;
};

// Why no worker could be started: the system call that failed and the system's message.
struct SpawnError {
    std::string call;
    std::string reason;
};

using Clock = std::chrono::steady_clock;

// Reads exactly `size` bytes unless the stream ends, fails or the deadline passes.
enum class ReadResult { Ok, Closed, TimedOut };
ReadResult receiveBefore(int fd, char* data, size_t size, Clock::time_point deadline) {
    while (size > 0) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return ReadResult::TimedOut;
        pollfd p{fd, POLLIN, 0};
        int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready < 0) return ReadResult::Closed;
        if (ready == 0) return ReadResult::TimedOut;
        ssize_t n = read(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return ReadResult::Closed;
        data += n;
        size -= static_cast<size_t>(n);
    }
    return ReadResult::Ok;
}

StageOutcome failure(StageOutcome::Status status, DiagId fault, std::vector<std::string> arguments) {
    StageOutcome outcome;
    outcome.status = status;
    outcome.fault = fault;
    outcome.faultArguments = std::move(arguments);
    return outcome;
}

// A worker that exited instead of answering: a sanitizer finding (its report is on standard error, which
// workers share with the compiler) or any other exit, on the shader or while idle.
StageOutcome exitedOutcome(int exitStatus, bool whileIdle) {
    const std::string status = std::to_string(exitStatus);
    if (exitStatus == kWorkerSanitizerExitStatus)
        return failure(
            StageOutcome::Status::SanitizerReport,
            whileIdle ? DiagId::CompileWorkerSanitizerReportWhileIdle : DiagId::CompileWorkerSanitizerReport,
            {status});
    return failure(StageOutcome::Status::Crashed,
                   whileIdle ? DiagId::CompileWorkerExitedWhileIdle : DiagId::HlslCompilerExited, {status});
}

}  // namespace

std::string findCompileWorker() {
    if (const char* env = std::getenv("SHADOWFX_COMPILE_WORKER"); env && *env)
        return isExecutable(env) ? std::string(env) : std::string();
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        std::string beside = (self.parent_path() / kWorkerName).string();
        if (isExecutable(beside)) return beside;
    }
#ifdef SHADOWFX_INSTALL_LIBEXECDIR
    if (std::string installed = std::string(SHADOWFX_INSTALL_LIBEXECDIR) + "/" + kWorkerName;
        isExecutable(installed))
        return installed;
#endif
#ifdef SHADOWFX_BUILD_TREE_WORKER
    if (isExecutable(SHADOWFX_BUILD_TREE_WORKER)) return SHADOWFX_BUILD_TREE_WORKER;
#endif
    return {};
}

struct CompileWorkers::Impl {
    CompileWorkerOptions options;
    std::string path;
    int maxWorkers = 1;

    mutable std::mutex mutex;
    std::condition_variable changed;
    std::vector<Worker> idle;
    std::vector<pid_t> live;  // idle and busy
    int starting = 0;         // being spawned (counted against maxWorkers)
    size_t replaced = 0;

    // An idle worker, or a new one while fewer than maxWorkers run; waits otherwise.
    bool acquire(Worker& worker, SpawnError& error) {
        {
            std::unique_lock<std::mutex> lock(mutex);
            changed.wait(
                lock, [&] { return !idle.empty() || static_cast<int>(live.size()) + starting < maxWorkers; });
            if (!idle.empty()) {
                worker = idle.back();
                idle.pop_back();
                return true;
            }
            ++starting;
        }
        bool ok = spawn(worker, error);
        std::lock_guard<std::mutex> lock(mutex);
        --starting;
        if (ok) live.push_back(worker.pid);
        changed.notify_all();
        return ok;
    }

    void release(const Worker& worker) {
        std::lock_guard<std::mutex> lock(mutex);
        idle.push_back(worker);
        changed.notify_all();
    }

    // Kills (unless it is already gone) and reaps a worker; returns its wait status, or -1.
    int discard(const Worker& worker, bool kill) {
        if (kill) ::kill(worker.pid, SIGKILL);
        int status = -1;
        // A worker that closed its stream is exiting; one that closed it and lingers is killed after 1 s.
        for (int i = 0; i < 100; ++i) {
            pid_t r = waitpid(worker.pid, &status, WNOHANG);
            if (r == worker.pid || (r < 0 && errno != EINTR)) break;
            if (i == 99) {
                ::kill(worker.pid, SIGKILL);
                waitpid(worker.pid, &status, 0);
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        close(worker.fd);
        std::lock_guard<std::mutex> lock(mutex);
        live.erase(std::remove(live.begin(), live.end(), worker.pid), live.end());
        ++replaced;
        changed.notify_all();
        return status;
    }

    // fork + exec: the child runs only async-signal-safe calls before exec (the parent may have GL driver
    // and compile threads holding locks); its end of the socket becomes its fd 0. A close-on-exec pipe
    // tells the parent whether exec worked: it closes empty on success, carries errno on failure.
    bool spawn(Worker& worker, SpawnError& error) {
        int sv[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
            error = {"socketpair", std::strerror(errno)};
            return false;
        }
        int status[2];
        if (pipe2(status, O_CLOEXEC) != 0) {
            error = {"pipe", std::strerror(errno)};
            close(sv[0]);
            close(sv[1]);
            return false;
        }
        char* argv[] = {const_cast<char*>(path.c_str()), nullptr};
        rlimit memory{options.memoryLimitMb << 20, options.memoryLimitMb << 20};
        rlimit noCore{0, 0};
        bool limitMemory = options.memoryLimitMb > 0 && !kAddressSanitizer;  // ASan reserves terabytes
        sigset_t none;
        sigemptyset(&none);
        pid_t pid = fork();
        if (pid == 0) {
            sigprocmask(SIG_SETMASK, &none, nullptr);
            if (limitMemory) setrlimit(RLIMIT_AS, &memory);
            setrlimit(RLIMIT_CORE, &noCore);
            if (sv[1] == 0 ? fcntl(0, F_SETFD, 0) == 0 : dup2(sv[1], 0) == 0) execv(path.c_str(), argv);
            int code = errno;
            ssize_t written = write(status[1], &code, sizeof code);
            (void)written;
            _exit(127);
        }
        int forkErrno = errno;
        close(sv[1]);
        close(status[1]);
        int execErrno = 0;
        ssize_t n = -1;
        if (pid > 0) do
                n = read(status[0], &execErrno, sizeof execErrno);
            while (n < 0 && errno == EINTR);
        close(status[0]);
        if (pid < 0 || n > 0) {
            close(sv[0]);
            if (pid > 0) waitpid(pid, nullptr, 0);
            error = pid < 0 ? SpawnError{"fork", std::strerror(forkErrno)}
                            : SpawnError{"exec", std::strerror(execErrno)};
            return false;
        }
        worker = Worker{pid, sv[0]};
        return true;
    }

    StageOutcome runOne(const std::string& request) {
        // One retry: a worker that died while idle (killed from outside) fails the send, not the job.
        for (int attempt = 0;; ++attempt) {
            Worker worker;
            SpawnError error;
            if (!acquire(worker, error))
                return failure(StageOutcome::Status::WorkerFailed, DiagId::CompileWorkerFailed,
                               {path, error.call, error.reason});
            if (!sendAll(worker.fd, request.data(), request.size())) {
                // Killed from outside while idle: replaced and sent again. A worker that exited by itself
                // while idle ran nothing since its last reply, yet its status is a finding, never dropped.
                const int status = discard(worker, true);
                if (status != -1 && WIFEXITED(status)) return exitedOutcome(WEXITSTATUS(status), true);
                if (attempt == 0) continue;
                return failure(StageOutcome::Status::WorkerFailed, DiagId::CompileWorkerRefusedRequest, {});
            }
            const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(options.timeLimitMs);
            char header[kFrameHeaderBytes];
            ReadResult read = receiveBefore(worker.fd, header, sizeof header, deadline);
            std::optional<FrameHeader> h;
            std::string payload;
            if (read == ReadResult::Ok) {
                h = parseFrameHeader(header);
                if (h && h->kind == FrameKind::Reply) {
                    payload.resize(h->payloadBytes);
                    read = receiveBefore(worker.fd, payload.data(), payload.size(), deadline);
                }
            }
            if (read == ReadResult::TimedOut) {
                discard(worker, true);
                StageOutcome outcome;
                outcome.status = StageOutcome::Status::TimedOut;
                return outcome;
            }
            if (read == ReadResult::Closed) {
                int status = discard(worker, false);
                if (status != -1 && WIFSIGNALED(status))
                    return failure(StageOutcome::Status::Crashed, DiagId::HlslCompilerCrashed,
                                   {std::to_string(WTERMSIG(status))});
                if (status != -1 && WIFEXITED(status)) return exitedOutcome(WEXITSTATUS(status), false);
                return failure(StageOutcome::Status::Crashed, DiagId::CompileWorkerConnectionClosed, {});
            }
            std::optional<StageOutcome> outcome;
            if (h && h->kind == FrameKind::Reply) outcome = decodeOutcome(payload);
            if (!outcome) {
                discard(worker, true);
                return failure(StageOutcome::Status::WorkerFailed, DiagId::CompileWorkerReplyUnreadable, {});
            }
            release(worker);
            return std::move(*outcome);
        }
    }
};

CompileWorkers::CompileWorkers(CompileWorkerOptions options) : mImpl(std::make_unique<Impl>()) {
    mImpl->options = std::move(options);
    mImpl->path = mImpl->options.workerPath.empty() ? findCompileWorker() : mImpl->options.workerPath;
    int cores = static_cast<int>(std::thread::hardware_concurrency());
    mImpl->maxWorkers = std::max(1, mImpl->options.maxWorkers > 0 ? mImpl->options.maxWorkers : cores);
}

CompileWorkers::~CompileWorkers() {
    std::lock_guard<std::mutex> lock(mImpl->mutex);
    for (const Worker& worker : mImpl->idle) close(worker.fd);  // end of stream: the worker exits
    for (const Worker& worker : mImpl->idle) {
        int status = 0;
        if (waitpid(worker.pid, &status, 0) != worker.pid || !WIFEXITED(status) || WEXITSTATUS(status) == 0)
            continue;  // reaped, or killed from outside while idle (as a compile would have found it)
        // A worker that failed on its way out reaches no compile and no caller. In a sanitizer build that
        // must still fail the run, as the sanitizers fail a process that ends with a finding: stop here.
        if (kAddressSanitizer) {
            std::fprintf(stderr,
                         "shadowfx-compile-worker (pid %d) exited with status %d after its last job\n",
                         static_cast<int>(worker.pid), WEXITSTATUS(status));
            std::abort();
        }
    }
}

CompileWorkers& CompileWorkers::shared() {
    static CompileWorkers pool;
    return pool;
}

bool CompileWorkers::available() const {
    return !mImpl->path.empty();
}
const std::string& CompileWorkers::workerPath() const {
    return mImpl->path;
}
int CompileWorkers::maxWorkers() const {
    return mImpl->maxWorkers;
}
int CompileWorkers::timeLimitMs() const {
    return mImpl->options.timeLimitMs;
}

std::vector<pid_t> CompileWorkers::workerPids() const {
    std::lock_guard<std::mutex> lock(mImpl->mutex);
    return mImpl->live;
}

size_t CompileWorkers::replacedWorkers() const {
    std::lock_guard<std::mutex> lock(mImpl->mutex);
    return mImpl->replaced;
}

std::vector<StageOutcome> CompileWorkers::run(const std::vector<StageJob>& jobs) {
    std::vector<StageOutcome> outcomes(jobs.size());
    std::atomic<size_t> next{0};
    auto drain = [&] {
        for (size_t i = next++; i < jobs.size(); i = next++)
            outcomes[i] = mImpl->runOne(frame(FrameKind::Request, encodeJob(jobs[i])));
    };
    // The calling thread is one of the senders; each sender waits on one worker at a time.
    const size_t senders = std::min<size_t>(jobs.size(), static_cast<size_t>(mImpl->maxWorkers));
    std::vector<std::thread> threads;
    for (size_t t = 1; t < senders; ++t) threads.emplace_back(drain);
    drain();
    for (std::thread& thread : threads) thread.join();
    return outcomes;
}

}  // namespace fx
