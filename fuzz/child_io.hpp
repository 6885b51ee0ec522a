// What a forked child and its parent share (fuzz/isolation.cpp, studies/run_child.cpp):
// the child's one way to write its pipe, and the name of the signal that killed it.
#pragma once
#include <string>

namespace dlab::fuzz {

// Writes all of s to fd, retrying after EINTR; when the parent is gone the
// child exits at once (status 1) without running destructors.
void write_all(int fd, const std::string& s);

// "SIGSEGV", "SIGXFSZ", ...: the signals a child may die of; nullptr for others.
const char* signal_name(int sig);

}  // namespace dlab::fuzz
