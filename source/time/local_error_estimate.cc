#include <deal.II/base/mpi.h>

#include <vesicle_iga/time/local_error_estimate.h>

#include <algorithm>
#include <cmath>

namespace vesicle_iga
{
  using namespace dealii;

  double
  local_error_norm(const dealii::TrilinosWrappers::MPI::Vector &U_new,
                   const dealii::TrilinosWrappers::MPI::Vector &U_n,
                   const dealii::TrilinosWrappers::MPI::Vector &U_nm1,
                   const double                                 dt,
                   const double                                 dt_prev,
                   const double                                 atol,
                   const double                                 rtol,
                   const std::vector<bool>                     *selected)
  {
    const double                          a = 1 + dt_prev / dt;
    dealii::TrilinosWrappers::MPI::Vector lte(U_new);
    lte *= 1 / a;
    lte.add(-1 / (a - 1), U_n, 1 / (a * (a - 1)), U_nm1);
    double      sum = 0;
    std::size_t k = 0, n = 0;
    for (const auto i : U_new.locally_owned_elements())
      {
        if (selected && !(*selected)[k++])
          continue;
        ++n;
        const double w
          = atol
            + rtol * std::max(std::abs(U_new[i]), std::abs(U_new[i] + lte[i]));
        sum += std::pow(lte[i] / w, 2);
      }
    const MPI_Comm comm = U_new.get_mpi_communicator();
    const double   N
      = selected ? Utilities::MPI::sum(double(n), comm) : double(U_new.size());
    return std::sqrt(Utilities::MPI::sum(sum, comm) / std::max(N, 1.));
  }
} // namespace vesicle_iga
