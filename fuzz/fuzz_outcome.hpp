// The fuzzer's outcome classes: variants/outcome.hpp's (ok, lower-dimensional,
// not-delaunay, invalid, reported, differs), which classify a result, and three
// that only a process can have, given when the child running a case x pair dies
// (fuzz/isolation.hpp): crash (a signal), timeout (its CPU-time limit or the
// wall-clock watchdog), out-of-memory (an allocation failed under its memory
// limit).
#pragma once
#include <string>
#include <string_view>

#include "variants/outcome.hpp"

namespace dlab::fuzz {

inline constexpr std::string_view kCrash = "crash";
inline constexpr std::string_view kTimeout = "timeout";
inline constexpr std::string_view kOutOfMemory = "out-of-memory";

// Every class, in the order summaries list them.
inline constexpr std::string_view kOutcomeOrder[] = {"ok",      "lower-dimensional", "not-delaunay",
                                                     "invalid", "reported",          "differs",
                                                     kCrash,    kTimeout,            kOutOfMemory};

// A failure: any class but ok and lower-dimensional.
inline bool is_failure(std::string_view outcome) { return outcome != "ok" && outcome != "lower-dimensional"; }

// What kind of failure, for signatures: the check group of `invalid`, the
// algorithm's message of `reported` with every run of digits replaced by '#'
// (so "walk exceeded 1200 steps" and "... 1300 steps" are one kind), cut to 80
// characters; empty for the other classes.
std::string detail_kind(const Outcome& o);
std::string message_kind(std::string_view message);

}  // namespace dlab::fuzz
