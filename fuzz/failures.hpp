// DIR/failures/: one point file per failure signature -- (algorithm, kernel,
// dimension, outcome class, kind of detail) -- holding the first case (lowest
// index) that showed it. A signature that already has its file keeps it, so a
// file appears once, when its signature is new to the directory. The files
// are derived from results.jsonl alone (the generators are deterministic), so
// a merged campaign writes the same files as the unsharded one.
//
// File: comment lines (signature, detail, case, seed, the command that replays
// the case, whether and how much it was shrunk, the command that replays the
// file's points), then the points -- shrunk (shrink_failure) -- as
// hexadecimal floats: a valid INPUT for `dlab triangulate` and `dlab shrink`.
// Beside it, where the pair made a mesh of those points, its picture.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/isolation.hpp"
#include "fuzz/record.hpp"
#include "fuzz/shrink_oracle.hpp"

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

// The point set written for a failure: `dlab shrink`'s (fuzz/shrink.hpp) on the
// case's points, each test a child process under the campaign's limits
// (fuzz/shrink_oracle.hpp), kept while the outcome class and kind persist. At
// most kCampaignShrinkTests tests, kCampaignShrinkSlowTests for timeout and
// out-of-memory (each of their tests may take the whole limit), so shrinking
// stays small beside a campaign: it runs once per new signature. A failure that
// does not show again in a fresh child (e.g. a DLAB_FUZZ_SELFTEST one) is
// written as generated. Deterministic where the pair's outcomes are (timeouts
// depend on the machine), so a merged campaign writes the same files.
inline constexpr std::uint64_t kCampaignShrinkTests = 400;
inline constexpr std::uint64_t kCampaignShrinkSlowTests = 12;
struct ShrunkFailure {
  PointSet points;
  bool shrunk = false;
  std::string note;    // the file's "# shrunk:" line, after "shrunk: "
  std::string detail;  // shrunk: the detail of the points written, from a last run of them
};
ShrunkFailure shrink_failure(const PointSet& points, const Pair& pair, std::uint64_t order_seed,
                             const FailureClass& failure, const Limits& limits);

class FailureIndex {
 public:
  void add(const PairRecord& r);
  std::size_t size() const { return first_.size(); }
  // Writes DIR/failures/STEM.txt for each signature that has no file yet,
  // shrunk under `limits`, and for not-delaunay and invalid failures a picture
  // of the pair's mesh of those points, STEM.svg (2D) or STEM.vtu (3D), faults
  // marked (fuzz/failure_mesh.hpp, cli/mesh_picture.hpp); returns how many
  // point files it wrote. Throws UsageError if it cannot write.
  std::size_t write(const std::string& dir, const CampaignSpec& spec, const Limits& limits) const;

 private:
  struct First {
    PairRecord record;  // the lowest case
    std::uint64_t count = 0;
  };
  std::map<Signature, First> first_;
};

}  // namespace dlab::fuzz
