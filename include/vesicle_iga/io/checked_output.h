#pragma once

#include <ostream>
#include <string>

namespace vesicle_iga
{
  /// Flushes @p out and throws a message naming @p filename if anything
  /// written to it was lost (no permission, disk full, quota or file size
  /// limit): a result file is never silently cut.
  void
  check_written(std::ostream &out, const std::string &filename);
} // namespace vesicle_iga
