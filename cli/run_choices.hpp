// The names that `dlab triangulate --policy/--order/--location` accept
// (design.md section 5), checked in one place for the command line (cli_app,
// dlab triangulate, dlab shrink) and the Python module.
#pragma once
#include <string>
#include <vector>

#include "variants/run.hpp"

namespace dlab::cli {

extern const std::vector<std::string> kPolicies;   // sos, strict
extern const std::vector<std::string> kOrders;     // input, random, brio, hilbert
extern const std::vector<std::string> kLocations;  // walk, scan

// "" if value is one of choices, else e.g. "--order must be input, random,
// brio or hilbert, not 'sideways'".
std::string choice_error(const std::string& option, const std::vector<std::string>& choices,
                         const std::string& value);

// Throws UsageError (the message above) for the first of opt.policy, opt.order
// and opt.location that is not one of its names.
void check_run_choices(const RunOptions& opt);

}  // namespace dlab::cli
