// The command line of one `dlab` subcommand, parsed by CLI11 (Debian
// libcli11-dev), with what every subcommand shares: the --help layout
// (synopsis, description, every option, examples), the mapping of every
// parse error to one stderr line and exit status 2 (design.md section 5), and
// options whose numbers go through cli/numbers.hpp (std::from_chars: correctly
// rounded, "1e-400" rejected as underflow), not CLI11's own conversion.
//
//   CommandLine cl("check", kSynopsis, kDescription, kExamples);
//   cl.app().add_option("INPUT", input, "the points")->required();
//   add_unsigned(cl.app(), "--seed", seed, UINT64_MAX, "seed of the order");
//   if (auto rc = cl.parse(argc, argv, 2)) return *rc;  // --help: 0, bad usage: 2
//
// A lone "-" is positional; so is a token that starts with '-' and a digit
// ("-1.5", "-0x1p-3"; CLI11: no option is named "-1"). "-.5" or "-inf" are
// positional after app().positionals_at_end(true) once the first positional
// is read (dlab predicate), or after "--". Option values may start with '-'
// ("--lo -2"). Options may be given as "--seed 7", "--seed=7" or "-o FILE";
// given twice, the last one counts (a std::vector positional takes them all).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dlab::cli {

class CommandLine {
 public:
  // command: the word after "dlab" in messages ("fuzz"); synopsis: the "usage: ..."
  // lines; description: what the command does; examples: command lines, shown
  // after "Examples:"; epilogue: text after them (exit statuses, ...).
  CommandLine(std::string command, std::string synopsis, std::string description,
              std::string examples, std::string epilogue = "");
  CLI::App& app() { return app_; }

  // Parses argv[first..argc). nullopt: go on. Otherwise the exit status to
  // return: 0 after --help (printed on stdout), 2 after a usage error (one
  // line "dlab COMMAND: problem" on stderr).
  std::optional<int> parse(int argc, char** argv, int first);

  // A usage error found after parse (e.g. two options that exclude each
  // other): the one stderr line, and 2.
  int usage_error(const std::string& message) const;

 private:
  // What CLI11 left over (allow_extras): "unknown option '--x'" (before any
  // unexpected positional), "unexpected argument 'y'", or nothing.
  std::optional<std::string> extras_error() const;

  std::string command_;
  CLI::App app_;
};

// The conversions behind the numeric options below (cli/numbers.hpp): a bad
// value throws CLI::ValidationError "NAME: 'x' is not an integer in LO..HI"
// (or numbers.hpp's reason for a real), which parse() reports as a usage error.
std::uint64_t parse_unsigned(const std::string& name, const std::string& text, std::uint64_t max);
std::int64_t parse_integer(const std::string& name, const std::string& text, std::int64_t lo,
                           std::int64_t hi);
double parse_real(const std::string& name, const std::string& text);

// Options whose value goes through those; the default --help shows is
// target's value at the call (clear it with ->default_str("") where none).
template <class T>
CLI::Option* add_unsigned(CLI::App& app, const std::string& name, T& target, std::uint64_t max,
                          const std::string& description) {
  auto* opt = app.add_option_function<std::string>(
      name, [&target, name, max](const std::string& s) { target = static_cast<T>(parse_unsigned(name, s, max)); },
      description);
  return opt->type_name("N")->default_str(std::to_string(target));
}
template <class T>
CLI::Option* add_integer(CLI::App& app, const std::string& name, T& target, std::int64_t lo,
                         std::int64_t hi, const std::string& description) {
  auto* opt = app.add_option_function<std::string>(
      name, [&target, name, lo, hi](const std::string& s) { target = static_cast<T>(parse_integer(name, s, lo, hi)); },
      description);
  return opt->type_name("N")->default_str(std::to_string(target));
}
CLI::Option* add_real(CLI::App& app, const std::string& name, double& target,
                      const std::string& description);
// One of choices, else "NAME must be a, b or c, not 'x'" (run_choices.hpp).
CLI::Option* add_choice(CLI::App& app, const std::string& name, std::string& target,
                        const std::vector<std::string>& choices, const std::string& description);
// --input-format FMT for the points file named by positional `input` (INPUT,
// POINTS): io::read_points's format names; an unknown one is reported by the
// reader, with the choices, as bad input.
CLI::Option* add_input_format(CLI::App& app, std::string& target, const std::string& input);

}  // namespace dlab::cli
