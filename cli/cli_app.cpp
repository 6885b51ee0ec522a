// See cli_app.hpp.
#include "cli/cli_app.hpp"

#include <iostream>
#include <memory>
#include <regex>
#include <sstream>
#include <string_view>
#include <utility>

#include "cli/numbers.hpp"
#include "cli/run_choices.hpp"

namespace dlab::cli {
namespace {

// --help: the synopsis first, then what the command does, every positional and
// option with its description, the examples and the epilogue.
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter(std::string synopsis, std::string description, std::string examples,
                std::string epilogue)
      : synopsis_(std::move(synopsis)),
        description_(std::move(description)),
        examples_(std::move(examples)),
        epilogue_(std::move(epilogue)) {
    column_width(30);
  }
  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override {
    std::ostringstream out;
    out << synopsis_;
    if (!description_.empty()) out << description_;
    out << make_positionals(app) << make_groups(app, mode) << "\nExamples:\n" << examples_;
    if (!epilogue_.empty()) out << "\n" << epilogue_;
    return out.str();
  }
  // A positional's line shows its name and description only.
  std::string make_option_opts(const CLI::Option* opt) const override {
    return opt->get_positional() ? std::string() : CLI::Formatter::make_option_opts(opt);
  }

 private:
  std::string synopsis_, description_, examples_, epilogue_;
};

// CLI11's message, in the words of design.md section 5 where they are clearer.
// The patterns are CLI11 2.x's texts; another text stands as CLI11 wrote it
// (still exit 2), and tests/test_cli.cmake would show the change.
std::string message_of(const CLI::ParseError& e) {
  const std::string what = e.what();
  std::smatch m;
  static const std::regex needs_value(R"(^(\S+): 1 required \S+ missing$)");
  static const std::regex required(R"(^(\S+) is required$)");
  static const std::regex excludes(R"(^(\S+) excludes (\S+)$)");
  static const std::regex flag_value(R"(^Could not convert: (\S+) = (.*)$)");  // our flags only convert
  if (std::regex_match(what, m, needs_value)) return "option " + m[1].str() + " needs a value";
  if (std::regex_match(what, m, required)) return "missing " + m[1].str();
  if (std::regex_match(what, m, excludes)) return m[1].str() + " and " + m[2].str() + " exclude each other";
  if (std::regex_match(what, m, flag_value))
    return "option " + m[1].str() + " takes no value (given '" + m[2].str() + "')";
  return what;
}

}  // namespace

CommandLine::CommandLine(std::string command, std::string synopsis, std::string description,
                         std::string examples, std::string epilogue)
    : command_(std::move(command)), app_("", "dlab " + command_) {
  app_.formatter(std::make_shared<HelpFormatter>(std::move(synopsis), std::move(description),
                                                 std::move(examples), std::move(epilogue)));
  app_.allow_extras(true);  // reported by parse() in this command's words
  // As before CLI11: an option given twice takes its last value.
  app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

int CommandLine::usage_error(const std::string& message) const {
  std::cerr << "dlab " << command_ << ": " << message << "\n";
  return 2;
}

std::optional<int> CommandLine::parse(int argc, char** argv, int first) {
  std::vector<std::string> args;  // CLI11 takes them last first
  for (int i = argc - 1; i >= first; --i) args.emplace_back(argv[i]);
  try {
    app_.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::cout << app_.help() << std::flush;
    return 0;
  } catch (const CLI::ParseError& e) {
    // An unknown option first: it may be why a value or an argument is missing.
    return usage_error(extras_error().value_or(message_of(e)));
  }
  if (auto e = extras_error()) return usage_error(*e);
  return std::nullopt;
}

std::optional<std::string> CommandLine::extras_error() const {
  const std::vector<std::string> extras = app_.remaining();
  std::optional<std::string> unexpected;
  for (const std::string& extra : extras) {
    if (extra == "--") continue;
    if (extra.size() > 1 && extra[0] == '-') return "unknown option '" + extra.substr(0, extra.find('=')) + "'";
    if (!unexpected) unexpected = "unexpected argument '" + extra + "'";
  }
  return unexpected;
}

std::uint64_t parse_unsigned(const std::string& name, const std::string& text, std::uint64_t max) {
  const auto v = io::parse_u64(text, max);
  if (!v) throw CLI::ValidationError(name, "'" + text + "' is not an integer in 0.." + std::to_string(max));
  return *v;
}

std::int64_t parse_integer(const std::string& name, const std::string& text, std::int64_t lo,
                           std::int64_t hi) {
  std::string_view s = text;
  const bool negative = !s.empty() && s.front() == '-';
  if (negative) s.remove_prefix(1);
  const auto v = io::parse_u64(s, std::uint64_t{1} << 62);
  const std::int64_t x = v ? (negative ? -static_cast<std::int64_t>(*v) : static_cast<std::int64_t>(*v)) : 0;
  if (!v || x < lo || x > hi)
    throw CLI::ValidationError(name, "'" + text + "' is not an integer in " + std::to_string(lo) + ".." +
                                         std::to_string(hi));
  return x;
}

double parse_real(const std::string& name, const std::string& text) {
  const io::ParsedDouble p = io::parse_double(text);
  if (p.status != io::ParseStatus::ok) throw CLI::ValidationError(name, io::describe(p.status, text));
  return p.value;
}

CLI::Option* add_real(CLI::App& app, const std::string& name, double& target,
                      const std::string& description) {
  auto* opt = app.add_option_function<std::string>(
      name, [&target, name](const std::string& s) { target = parse_real(name, s); }, description);
  return opt->type_name("X")->default_str(io::format_decimal(target));
}

CLI::Option* add_choice(CLI::App& app, const std::string& name, std::string& target,
                        const std::vector<std::string>& choices, const std::string& description) {
  std::string names;
  for (const std::string& c : choices) names += (names.empty() ? "" : "|") + c;
  auto* opt = app.add_option_function<std::string>(
      name,
      [&target, name, choices](const std::string& s) {
        if (std::string e = choice_error(name, choices, s); !e.empty()) throw CLI::ValidationError(e);
        target = s;
      },
      description);
  return opt->type_name(names)->default_str(target);
}

CLI::Option* add_input_format(CLI::App& app, std::string& target, const std::string& input) {
  return app
      .add_option("--input-format", target,
                  "text, node, xyz, off or ply, whatever " + input +
                      "'s extension (default: by the extension;\nstandard input: text)")
      ->type_name("FMT");
}

}  // namespace dlab::cli
