// The subcommands of `dlab` (design.md section 5). Each returns the exit
// status: 0 success, 1 failure of the algorithm / an invalid result, 2 bad
// input or usage. argv[0] is "dlab", argv[1] the subcommand name.
#pragma once

namespace dlab::cli {

int cmd_triangulate(int argc, char** argv);
int cmd_check(int argc, char** argv);
int cmd_convert(int argc, char** argv);
int cmd_predicate(int argc, char** argv);
int cmd_gen(int argc, char** argv);
int cmd_demo(int argc, char** argv);
int cmd_draw(int argc, char** argv);
int cmd_voronoi(int argc, char** argv);
int cmd_flip(int argc, char** argv);
int cmd_plot(int argc, char** argv);
int cmd_fuzz(int argc, char** argv);
int cmd_corpus(int argc, char** argv);
int cmd_shrink(int argc, char** argv);
int cmd_study(int argc, char** argv);
int cmd_version(int argc, char** argv);

}  // namespace dlab::cli
