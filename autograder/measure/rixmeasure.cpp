// rixmeasure: answers the autograder's questions about one plugin.
//
//   rixmeasure PLUGIN FOLDER    (requests on descriptor 3, answers on 4)
//
// The grader runs it in a sandbox with the student's plugin, sends requests
// in the fixed format of labkit/measure/Wire.h (directions, points and
// random numbers it chose) and reads back raw measurements; it judges them
// itself. Nothing here decides a grade. What the plugin prints goes to
// stdout/stderr, which the grader keeps apart (and caps).
#include <cstdio>
#include <exception>
#include <string>

#include "measure/ProbeMeasurer.h"
#include "measure/Wire.h"

int main(int argc, char** argv) {
    bxdflab::wire::keepBatchBuffersOnHeap();
    if (argc != 3) {
        std::fprintf(stderr, "usage: rixmeasure PLUGIN FOLDER (requests on fd 3, answers on fd 4)\n");
        return 2;
    }
    try {
        bxdflab::Diagnostics diagnostics;  // the plugin's own messages go to stderr
        bxdflab::ProbeMeasurer measurer(argv[1], {argv[2]}, diagnostics, bxdflab::wire::announceCall);
        bxdflab::wire::serve(3, 4, measurer);
    } catch (std::exception const& e) {
        std::fprintf(stderr, "rixmeasure: %s\n", e.what());
        return 1;
    }
    return 0;
}
