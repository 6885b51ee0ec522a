// `dlab fuzz merge DIR... --out DIR`: the shards of one campaign (the same
// campaign.json but for --shard k/n, every k from 1 to n once) combined into
// what the unsharded campaign writes: campaign.json with shard 1/1,
// results.jsonl in case order (case i is in shard 1 + i mod n, so the merge
// takes groups round robin), summary.txt and failures/. With --no-timing
// (every record's seconds 0) the merged directory is byte-identical to the
// unsharded one; otherwise only the seconds differ. Shards of a --budget
// campaign ran different numbers of cases: their merge is the union, in case
// order, with gaps where a shard stopped earlier (it cannot be resumed).
#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace dlab::fuzz {

// Returns 1 if an exact pair failed in the merged campaign, else 0; throws
// UsageError (exit 2) for directories that are not the complete shards of one
// campaign, or an output directory that already holds results.
int merge_campaigns(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& out);

}  // namespace dlab::fuzz
