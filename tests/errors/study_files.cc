// Every study file in prm/ must read without error: a misspelt parameter
// name or a value outside its pattern in a study that takes hours would
// otherwise show only when someone runs it. Each file goes through
// `vesicle-iga --check FILE` (the parser of the real program, nothing is
// run); a last case checks that a misspelt name does fail. Expected output:
// exit code 0 and the study of each file (checked against the files' own
// "set Study" and "set Dimension" lines), exit code 1 and the message
// naming the misspelt entry for the last case.

#include <deal.II/base/mpi.h>

#include <vesicle_iga/app/program.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
  /// Runs the program with @p args and returns its exit code and what it
  /// printed to stdout and stderr.
  std::pair<int, std::string>
  run(const std::vector<std::string> &args)
  {
    std::ostringstream captured;
    auto              *old_out = std::cout.rdbuf(captured.rdbuf());
    auto              *old_err = std::cerr.rdbuf(captured.rdbuf());
    const int          code    = vesicle_iga::run_program(args);
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    return {code, captured.str()};
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out("output");
  const std::filesystem::path here = std::filesystem::current_path();

  // Paths relative to the source tree, so that the output does not depend
  // on where it is.
  std::filesystem::current_path(VESICLE_IGA_SOURCE_DIR);
  std::vector<std::string> files;
  for (const auto &entry : std::filesystem::directory_iterator("prm"))
    if (entry.path().extension() == ".prm")
      files.push_back(entry.path().generic_string());
  std::sort(files.begin(), files.end());
  for (const auto &file : files)
    {
      const auto [code, text] = run({"--check", file});
      out << "exit code " << code << ": " << text;
    }
  std::filesystem::current_path(here);

  std::ofstream("misspelt.prm") << "set Study = willmore-flow\n"
                                << "subsection Willmore flow\n"
                                << "  set Semi-axis = 2, 1\nend\n";
  const auto [code, text] = run({"--check", "misspelt.prm"});
  out << "exit code " << code << ": " << text;
}
