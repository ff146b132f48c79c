// The two small studies of the reliability tests: a Willmore flow of a
// circle (2D, 32^2 elements, p = 3, direct solver; 8 steps take about 2 s on
// one rank) and the lid-driven cavity (RBVMS, Re = 100, 16^2, p = 2, fixed
// dt; steps of about 50 ms, iterative solver, any number of ranks).
#pragma once

#include <fstream>
#include <string>

/// The circle flow with @p steps steps into @p directory; @p time_stepping
/// and @p extra are added to its time-stepping and Willmore flow
/// subsections.
inline std::string
circle_flow(const unsigned int steps,
            const std::string &directory,
            const std::string &time_stepping = "",
            const std::string &extra         = "")
{
  return "set Study = willmore-flow\n"
         "set Print details = false\n"
         "set Output directory = "
         + directory
         + "\n"
           "subsection Willmore flow\n"
           "set Semi-axes = 1\nset Center = 0,0\n"
           "subsection Linear solver\nset Method = direct\nend\n"
           "subsection Mesh\nset Lower corner = -3.2\n"
           "set Upper corner = 3.2\nset Elements = 32\nend\n"
         + extra
         + "subsection Time stepping\nset End time = 10\n"
           "set Initial dt = 1e-3\nset Max dt = 0.05\n"
           "set Checkpoint interval = 2\nset Max steps = "
         + std::to_string(steps) + "\n" + time_stepping + "end\nend\n";
}

/// The cavity with @p steps steps into @p directory.
inline std::string
cavity_flow(const unsigned int steps,
            const std::string &directory,
            const std::string &time_stepping = "")
{
  return "set Study = navier-stokes\n"
         "set Print details = false\n"
         "set Output directory = "
         + directory
         + "\n"
           "subsection Navier-Stokes\nset Reynolds number = 100\n"
           "subsection Mesh\nset Elements = 16\nend\n"
           "subsection Boundary 1\nset Type = strong\n"
           "set Where = x-min; x-max; y-min\nset Velocity = 0; 0\nend\n"
           "subsection Boundary 2\nset Type = weak\nset Where = y-max\n"
           "set Velocity = 1; 0\nend\n"
           "subsection Time stepping\nset Initial dt = 0.01\nset Max dt = 0.01\n"
           "set Step control = fixed\nset End time = 1e9\n"
           "set Steady tolerance = 0\nset rho_inf = 0.5\n"
           "set Checkpoint interval = 2\nset Max steps = "
         + std::to_string(steps) + "\n" + time_stepping + "end\nend\n";
}

/// Writes @p text to @p filename and returns the name.
inline std::string
write_prm(const std::string &filename, const std::string &text)
{
  std::ofstream(filename) << text;
  return filename;
}
