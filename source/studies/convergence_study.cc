#include <vesicle_iga/postprocess/convergence_study_table.h>
#include <vesicle_iga/studies/convergence_study.h>

namespace vesicle_iga
{
  void
  run_convergence_study(
    const RunContext               &context,
    const unsigned int              dim,
    const ConvergenceParameters    &convergence,
    const std::vector<std::string> &norm_names,
    const std::function<ConvergenceLevel(unsigned int, unsigned int)>
                      &solve_level,
    const std::string &legend)
  {
    ConvergenceStudyTable table(dim, norm_names);
    for (const unsigned int p : convergence.degrees)
      for (unsigned int r = 0; r <= convergence.refinements; ++r)
        {
          const ConvergenceLevel level = solve_level(p, r);
          table.add_row(p, level.elements, level.dofs, level.h, level.errors);
          context.pcout << "p=" << p << " level=" << r
                        << " elements=" << level.elements
                        << " unknowns=" << level.dofs;
          if (context.print_details)
            context.pcout << " iterations=" << level.solve.iterations
                          << " relative-residual=" << level.solve.residual;
          context.pcout << std::endl;
        }
    if (!legend.empty())
      context.pcout << legend << std::endl;
    table.report(context.pcout, context.communicator, context.output_directory);
  }
} // namespace vesicle_iga
