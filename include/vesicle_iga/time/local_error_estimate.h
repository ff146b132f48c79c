#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace vesicle_iga
{
  /**
   * The weighted RMS norm of the local truncation error estimate (N5) of
   * spec section 2.5 (order 2, from three levels U_{n+1}, U_n, U_{n-1}
   * with steps dt = t_{n+1} - t_n and dt_prev = t_n - t_{n-1}):
   *   LTE = U_{n+1}/a - U_n/(a-1) + U_{n-1}/(a(a-1)),  a = 1 + dt_prev/dt,
   *   e   = sqrt(1/N sum_j (LTE_j / (atol + rtol max(|U_j|, |U_j+LTE_j|)))^2).
   * @p selected (optional, one flag per locally owned entry): the sum and
   * N run over the selected entries only (e.g. the phase fields of a
   * model whose other fields follow them quasi-statically).
   */
  double
  local_error_norm(const dealii::TrilinosWrappers::MPI::Vector &U_new,
                   const dealii::TrilinosWrappers::MPI::Vector &U_n,
                   const dealii::TrilinosWrappers::MPI::Vector &U_nm1,
                   const double                                 dt,
                   const double                                 dt_prev,
                   const double                                 atol,
                   const double                                 rtol,
                   const std::vector<bool> *selected = nullptr);
} // namespace vesicle_iga
