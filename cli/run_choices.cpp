// See run_choices.hpp.
#include "cli/run_choices.hpp"

namespace dlab::cli {

const std::vector<std::string> kPolicies = {"sos", "strict"};
const std::vector<std::string> kOrders = {"input", "random", "brio", "hilbert"};
const std::vector<std::string> kLocations = {"walk", "scan"};

std::string choice_error(const std::string& option, const std::vector<std::string>& choices,
                         const std::string& value) {
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i] == value) return "";
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  }
  return option + " must be " + list + ", not '" + value + "'";
}

void check_run_choices(const RunOptions& opt) {
  for (const std::string& e : {choice_error("--policy", kPolicies, opt.policy),
                               choice_error("--order", kOrders, opt.order),
                               choice_error("--location", kLocations, opt.location)})
    if (!e.empty()) throw UsageError(e);
}

}  // namespace dlab::cli
