#include <vesicle_iga/io/checked_output.h>

#include <stdexcept>

namespace vesicle_iga
{
  void
  check_written(std::ostream &out, const std::string &filename)
  {
    out.flush();
    if (!out)
      throw std::runtime_error("cannot write " + filename
                               + " (no permission, disk full, quota or file "
                                 "size limit?)");
  }
} // namespace vesicle_iga
