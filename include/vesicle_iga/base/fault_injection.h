#pragma once

namespace vesicle_iga
{
  /**
   * Test-only faults, so that the tests of issue 17 can make a run fail the
   * way clusters make it fail, at a chosen point. Switched on by the
   * environment variable VESICLE_IGA_TEST_FAULT, a comma-separated list of
   * "point:n" (fail the n-th time the point is reached, counting from 1)
   * or "point:n+" (the n-th time and every time after). Normal runs never set
   * it; then every query is one branch. The points:
   *  - checkpoint-write: the process is killed (SIGKILL) in the middle of
   *    writing a checkpoint (half of checkpoint.h5.tmp written);
   *  - series-write: killed in the middle of a row of the time series;
   *  - vtu-write: killed in the middle of writing the VTU files (its own
   *    .vtu or .pvtu cut to half);
   *  - rank-1-throws: rank 1 alone throws after an accepted step;
   *  - nan-residual: the residual of a Newton iteration has a NaN in the
   *    last rank's part.
   * The tests in tests/reliability use them.
   */
  bool
  fault_requested(const char *point);

  /// Kill this process as kill -9 would.
  [[noreturn]] void
  kill_process();
} // namespace vesicle_iga
