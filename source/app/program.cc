#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/app/program.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/studies/study.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      std::string names;
      for (const auto &s : available_studies())
        names += (names.empty() ? "" : "|") + s.name;
      prm.declare_entry("Study",
                        available_studies().front().name,
                        Patterns::Selection(names),
                        "Which study this file runs; its parameters are in "
                        "the subsection of the same title.");
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension of the study (2 or 3).");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Where results go (created if missing); relative to "
                        "the working directory.");
      prm.declare_entry("Print details",
                        "true",
                        Patterns::Bool(),
                        "Print iteration counts, residuals and a timing "
                        "summary. Tests switch this off so that their output "
                        "does not depend on the machine or the partition.");
      for (const auto &s : available_studies())
        s.declare_parameters(prm);
    }

    const char *usage
      = "Usage: vesicle-iga FILE.prm     run the study described in FILE.prm\n"
        "       vesicle-iga -            read the parameter file from stdin\n"
        "       vesicle-iga --check FILE.prm\n"
        "                                only read FILE.prm and report whether\n"
        "                                every name and value is valid\n"
        "       vesicle-iga --print-parameters\n"
        "                                print every parameter with its "
        "default,\n"
        "                                allowed values and documentation\n"
        "       vesicle-iga --help       this text and the list of studies\n"
        "Run in parallel with: mpirun -np N vesicle-iga FILE.prm\n";

    /// The part of a deal.II exception that describes the problem.
    std::string
    describe(const ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      std::string text = s.str();
      const auto  pos  = text.find("Additional information:");
      if (pos != std::string::npos)
        text = text.substr(pos + 23);
      return Utilities::trim(text);
    }
  } // namespace


  int
  run_program(const std::vector<std::string> &args)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    ConditionalOStream pcout(std::cout, root);
    ConditionalOStream perr(std::cerr, root);
    try
      {
        ParameterHandler prm;
        declare_parameters(prm);
        const bool check_only = args.size() == 2 && args[0] == "--check";
        if ((args.size() != 1 && !check_only) || args[0] == "--help"
            || args[0] == "-h")
          {
            pcout << usage << "\nStudies:\n";
            for (const auto &s : available_studies())
              pcout << "  " << s.name << ": " << s.summary << "\n";
            return args.size() == 1 ? 0 : 2;
          }
        if (args[0] == "--print-parameters")
          {
            if (root)
              prm.print_parameters(std::cout, ParameterHandler::PRM);
            return 0;
          }

        // Read the file on rank 0 (stdin exists only there) and share it.
        std::string text, name = args.back();
        if (root)
          {
            std::stringstream buffer;
            if (name == "-")
              {
                buffer << std::cin.rdbuf();
                name = "standard input";
              }
            else
              {
                std::ifstream file(name);
                if (file)
                  buffer << file.rdbuf();
                else
                  text = "\x01";
              }
            if (text.empty())
              text = buffer.str();
          }
        text = Utilities::MPI::broadcast(comm, text, 0);
        check_input(text != "\x01",
                    "parameter file",
                    name,
                    "the path of a readable .prm file (or - for standard "
                    "input)");
        // As a stream, so that a message names the file (the second
        // argument of parse_input_from_string is a terminating line).
        std::istringstream stream(text);
        prm.parse_input(stream, name);
        if (check_only)
          {
            // Names and values are checked by the parser; what depends on
            // several parameters (the vesicle fits the box, ...) is checked
            // when the study is set up.
            pcout << name << ": valid parameters for study " << prm.get("Study")
                  << ", dimension " << prm.get("Dimension") << std::endl;
            return 0;
          }

        RunContext context{comm,
                           static_cast<unsigned int>(
                             prm.get_integer("Dimension")),
                           prm.get("Output directory"),
                           prm.get_bool("Print details"),
                           pcout};
        if (root)
          {
            std::filesystem::create_directories(context.output_directory);
            std::ofstream used(context.output_directory
                               + "/parameters-used.prm");
            prm.print_parameters(used, ParameterHandler::ShortPRM);
          }
        MPI_Barrier(comm);

        const std::string study_name = prm.get("Study");
        for (const auto &s : available_studies())
          if (s.name == study_name)
            {
              pcout << "vesicle-iga: study " << study_name << ", dimension "
                    << context.dimension << ", "
                    << Utilities::MPI::n_mpi_processes(comm)
                    << " MPI rank(s), output in " << context.output_directory
                    << std::endl;
              s.create(prm, context)->run();
              if (context.print_details)
                {
                  // Peak resident memory (VmHWM) per rank, for benchmarks.
                  Utilities::System::MemoryStats m;
                  Utilities::System::get_memory_stats(m);
                  const auto peak
                    = Utilities::MPI::min_max_avg(m.VmHWM / 1024., comm);
                  pcout << "peak memory (VmHWM) per rank: max " << peak.max
                        << " MB, sum " << peak.sum << " MB" << std::endl;
                }
            }
        return 0;
      }
    catch (const InputError &e)
      {
        perr << "vesicle-iga: error: " << e.what() << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        perr << "vesicle-iga: error: " << describe(e) << std::endl;
      }
    catch (const std::exception &e)
      {
        perr << "vesicle-iga: error: " << e.what() << std::endl;
      }
    return 1;
  }
} // namespace vesicle_iga
