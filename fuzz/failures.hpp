// DIR/failures/: one point file per failure signature -- (algorithm, kernel,
// dimension, outcome class, kind of detail) -- holding the first case (lowest
// index) that showed it. A signature that already has its file keeps it, so a
// file appears once, when its signature is new to the directory. The files
// are derived from results.jsonl alone (the generators are deterministic), so
// a merged campaign writes the same files as the unsharded one.
//
// File: comment lines (signature, detail, case, seed, the command that replays
// it, whether it was shrunk), then the points as hexadecimal floats -- a valid
// INPUT for `dlab triangulate` and `dlab shrink`.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {

struct Signature {
  std::string algo, kernel;
  int dim = 2;
  std::string outcome, kind;
  auto tie() const { return std::tie(algo, kernel, dim, outcome, kind); }
  bool operator<(const Signature& o) const { return tie() < o.tie(); }
  // A file name: "ALGO.KERNEL.Dd.OUTCOME[.KIND-HASH]", [a-z0-9.+-] only; the
  // hash (FNV-1a of the kind) keeps kinds apart that read alike after cleaning.
  std::string file_stem() const;
};

// The shrinker's hook: the point set written for a failure. Returns the points
// unchanged and sets `shrunk` false until `dlab shrink` (issue 12) plugs in
// here (same pair, same outcome class, fewer and simpler points).
PointSet shrink_failure(const PointSet& points, const Pair& pair, std::string_view outcome, bool& shrunk);

class FailureIndex {
 public:
  void add(const PairRecord& r);
  std::size_t size() const { return first_.size(); }
  // Writes DIR/failures/STEM.txt for each signature that has no file yet;
  // returns how many it wrote. Throws UsageError if it cannot write.
  std::size_t write(const std::string& dir, const CampaignSpec& spec) const;

 private:
  struct First {
    PairRecord record;  // the lowest case
    std::uint64_t count = 0;
  };
  std::map<Signature, First> first_;
};

}  // namespace dlab::fuzz
