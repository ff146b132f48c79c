// Bad input must give one clear message naming the parameter, the value and
// what is allowed, and a non-zero exit code; never a crash. Each case runs
// the real program entry point on a parameter text and prints the exit code
// and the message (checked by hand: each names its parameter and value).

#include <deal.II/base/mpi.h>

#include <vesicle_iga/app/program.h>

#include <fstream>
#include <iostream>
#include <sstream>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize               mpi(argc, argv, 1);
  std::ofstream                                          out("output");
  const std::vector<std::pair<std::string, std::string>> cases
    = {{"unknown parameter", "set Study = poisson-mms\nset Degreez = 3\n"},
       {"biharmonic on C^0 (degree 1)",
        "set Study = biharmonic-mms\nsubsection Biharmonic MMS\n"
        "set Degrees = 1\nend\n"},
       {"biharmonic with continuity 0",
        "set Study = biharmonic-mms\nsubsection Biharmonic MMS\n"
        "set Degrees = 3\nset Continuity = 0\nend\n"},
       {"continuity not below the degree",
        "set Study = poisson-mms\nsubsection Poisson MMS\n"
        "set Degrees = 2\nset Continuity = 2\nend\n"},
       {"empty breakpoint list",
        "set Study = poisson-mms\nsubsection Poisson MMS\nset Degrees = 2\n"
        "subsection Mesh\nset Breakpoints x = 0.5\nend\nend\n"},
       {"decreasing breakpoints",
        "set Study = poisson-mms\nsubsection Poisson MMS\nset Degrees = 2\n"
        "subsection Mesh\nset Breakpoints x = 0, 0.5, 0.4, 1\nend\nend\n"},
       {"malformed boundary selection",
        "set Study = poisson-mms\nsubsection Poisson MMS\n"
        "set Nitsche boundaries = left\nend\n"},
       {"plate in 3D", "set Study = plate-with-hole\nset Dimension = 3\n"},
       {"unknown study", "set Study = nonsense\n"},
       {"vesicle does not fit in the domain",
        "set Study = willmore-flow\nsubsection Willmore flow\n"
        "set Semi-axes = 1.8\nend\n"},
       {"epsilon too small for the mesh",
        "set Study = willmore-flow\nsubsection Willmore flow\n"
        "set Epsilon over h = 0.5\nend\n"},
       {"sphere with unequal semi-axes",
        "set Study = willmore-flow\nsubsection Willmore flow\n"
        "set Semi-axes = 1, 0.5\nend\n"},
       {"flow velocity with the wrong number of components",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "subsection Boundary 1\nset Type = strong\nset Where = all\n"
        "set Velocity = 1\nend\nend\n"},
       {"flow formula with an unknown symbol",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "set Body force = 0; gravity\nend\n"},
       {"negative Reynolds number",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "set Reynolds number = -5\nend\n"},
       {"line sample reference unknown",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "subsection Line sample 1\nset Name = c\nset Start = 0.5, 0\n"
        "set End = 0.5, 1\nset Reference = ghia-1983\nend\nend\n"},
       // Found by tools/fuzz-prm.py (doc/reliability.md): a line sample
       // along which its abscissa does not change (the reference data
       // were interpolated at 0 / 0: a segmentation fault), one that leaves
       // the domain, and a boundary range with a non-finite end.
       {"line sample with constant abscissa",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "subsection Line sample 1\nset Name = c\nset Start = 0.5, 0\n"
        "set End = 1, 0\nset Coordinate = y\n"
        "set Reference = ghia-1982-re100-u\nend\nend\n"},
       {"line sample outside the domain",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "subsection Line sample 1\nset Name = c\nset Start = 0.5, 0\n"
        "set End = 0.5, 2\nend\nend\n"},
       {"boundary range with an infinite end",
        "set Study = navier-stokes\nsubsection Navier-Stokes\n"
        "subsection Boundary 1\nset Type = strong\n"
        "set Where = y-min{x:0:inf}\nend\nend\n"},
       {"3D vesicles in a 2D box",
        "set Study = vesicle-hydrodynamics\nset Dimension = 3\n"},
       {"3D vesicles given in the 2D format",
        "set Study = vesicle-hydrodynamics\nset Dimension = 3\n"
        "subsection Vesicle hydrodynamics\nsubsection Mesh\n"
        "set Lower corner = -2\nset Upper corner = 2\nset Elements = 8\n"
        "end\nset Vesicles = 0, 0, 0.863, 0.84, 90\nend\n"},
       {"reduced volume above 1",
        "set Study = vesicle-hydrodynamics\nset Dimension = 3\n"
        "subsection Vesicle hydrodynamics\nsubsection Mesh\n"
        "set Lower corner = -2\nset Upper corner = 2\nset Elements = 8\n"
        "end\nset Vesicles = 0, 0, 0, 0.863, 1.1, 90\nend\n"},
       {"2D perimeter formula in 3D",
        "set Study = vesicle-hydrodynamics\nset Dimension = 3\n"
        "subsection Vesicle hydrodynamics\nsubsection Mesh\n"
        "set Lower corner = -2\nset Upper corner = 2\nset Elements = 8\n"
        "end\nset Vesicles = 0, 0, 0, 0.863, 0.9, 90\n"
        "set Stretch formula = quadratic-mean\nend\n"},
       {"vesicles on quadratic splines",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\nset Degree = 2\nend\n"},
       {"reduced area above 1",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\n"
        "set Vesicles = 0, 0, 0.863, 1.2, 90\nend\n"},
       {"vesicle too close to the boundary",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\n"
        "set Vesicles = 1.5, 0, 0.863, 0.84, 90\nend\n"},
       {"overlapping vesicles",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\n"
        "set Vesicles = -0.2, 0, 0.7, 0.84, 90; 0.2, 0, 0.7, 0.84, 90\n"
        "end\n"},
       {"interface narrower than the mesh",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\nset Epsilon = 0.05\nend\n"},
       {"vesicle entry with three numbers",
        "set Study = vesicle-hydrodynamics\n"
        "subsection Vesicle hydrodynamics\n"
        "set Vesicles = 0, 0, 0.863\nend\n"}};
  for (const auto &[name, text] : cases)
    {
      std::ofstream("case.prm") << "set Output directory = results\n" << text;
      std::ostringstream captured;
      auto              *old  = std::cerr.rdbuf(captured.rdbuf());
      const int          code = vesicle_iga::run_program({"case.prm"});
      std::cerr.rdbuf(old);
      out << "case: " << name << "\n  exit code " << code << "\n  "
          << captured.str();
    }
  std::ostringstream captured;
  auto              *old  = std::cerr.rdbuf(captured.rdbuf());
  const int          code = vesicle_iga::run_program({"no-such-file.prm"});
  std::cerr.rdbuf(old);
  out << "case: missing file\n  exit code " << code << "\n  " << captured.str();
}
