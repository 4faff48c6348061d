// CompileProtocol: the messages between the compiler and a compile worker process (CompileWorkers.h),
// over a stream socket. Every message is a frame:
//
//   u32 magic 'SFXW' | u32 protocol version | u32 kind | u32 payload bytes | payload
//
// little-endian (both ends are the same build on the same machine; the magic and version catch a worker
// binary from another build). A request (kind 1) carries a StageJob, a reply (kind 2) a StageOutcome.
// Payload fields are u32 integers and length-prefixed byte strings, in the order of the encode functions.
#pragma once

#include "StageCompile.h"

#include <cstdint>
#include <optional>
#include <string>

namespace fx {

inline constexpr uint32_t kProtocolMagic = 0x57584653;  // "SFXW"
inline constexpr uint32_t kProtocolVersion = 6;
inline constexpr uint32_t kFrameHeaderBytes = 16;
inline constexpr uint32_t kMaxFramePayload = 256u << 20;

enum class FrameKind : uint32_t { Request = 1, Reply = 2 };

std::string encodeJob(const StageJob& job);
std::optional<StageJob> decodeJob(const std::string& payload);
std::string encodeOutcome(const StageOutcome& outcome);
std::optional<StageOutcome> decodeOutcome(const std::string& payload);

// Header + payload.
std::string frame(FrameKind kind, const std::string& payload);
// Parses a header; nullopt if the magic, version or size is wrong. Returns the kind and payload size.
struct FrameHeader {
    FrameKind kind;
    uint32_t payloadBytes;
};
std::optional<FrameHeader> parseFrameHeader(const char* header);

// Blocking whole-buffer socket I/O, retried on EINTR; false on error or end of stream. sendAll never
// raises SIGPIPE (the peer may be a crashed worker).
bool sendAll(int fd, const char* data, size_t size);
bool receiveAll(int fd, char* data, size_t size);

// The exit status of a worker that stopped on a sanitizer finding (an AddressSanitizer, UBSan or
// LeakSanitizer report on its standard error) instead of answering: the worker sets it as the sanitizers'
// `exitcode` and uses it after its own leak check, and the compiler reports it as such, never as an
// ordinary crash.
inline constexpr int kWorkerSanitizerExitStatus = 86;

// The worker side: answers requests on `fd` until the stream ends; returns the process exit status.
// `jobLeftNoFinding`, when given, runs after each job and before its reply; false ends the worker with
// kWorkerSanitizerExitStatus and no reply (the sanitized worker's leak check).
int serveCompileRequests(int fd, bool (*jobLeftNoFinding)() = nullptr);

}  // namespace fx
