#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/app/program.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/base/interrupt.h>
#include <vesicle_iga/io/checked_output.h>
#include <vesicle_iga/io/output_lock.h>
#include <vesicle_iga/studies/study.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <iostream>
#include <sstream>
#include <thread>

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


  namespace
  {
    /// The text of the parameter file @p name (or standard input for "-",
    /// then @p name becomes "standard input"), read on rank 0 (stdin exists
    /// only there) and shared.
    std::string
    read_parameter_file(std::string &name, const MPI_Comm comm)
    {
      std::string text;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
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
      name = Utilities::MPI::broadcast(comm, name, 0);
      check_input(text != "\x01",
                  "parameter file",
                  name,
                  "the path of a readable .prm file (or - for standard "
                  "input)");
      return text;
    }


    /// The output directory, created, locked for this run (the lock is
    /// returned), with the parameters used.
    std::unique_ptr<OutputLock>
    prepare_output_directory(const ParameterHandler &prm,
                             const RunContext       &context)
    {
      const bool root
        = Utilities::MPI::this_mpi_process(context.communicator) == 0;
      if (root)
        std::filesystem::create_directories(context.output_directory);
      MPI_Barrier(context.communicator);
      auto lock = std::make_unique<OutputLock>(context.output_directory,
                                               context.communicator);
      if (root)
        {
          const std::string used_name
            = context.output_directory + "/parameters-used.prm";
          std::ofstream used(used_name);
          prm.print_parameters(used, ParameterHandler::ShortPRM);
          check_written(used, used_name);
        }
      return lock;
    }


    /// Parse the arguments and the parameter file, run the study; returns
    /// the exit code. Errors are thrown.
    int
    run_arguments(const std::vector<std::string> &args,
                  const MPI_Comm                  comm,
                  ConditionalOStream             &pcout)
    {
      const bool       root = Utilities::MPI::this_mpi_process(comm) == 0;
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

      std::string       name = args.back();
      const std::string text = read_parameter_file(name, comm);
      // As a stream, so that a message names the file (the second
      // argument of parse_input_from_string is a terminating line).
      std::istringstream stream(text);
      prm.parse_input(stream, name);
      RunContext context{comm,
                         static_cast<unsigned int>(
                           prm.get_integer("Dimension")),
                         prm.get("Output directory"),
                         prm.get_bool("Print details"),
                         pcout};
      if (check_only)
        {
          // Names and values are checked by the parser; what depends on
          // several parameters (continuity and degree, the mesh, formulas,
          // ...) by the study's constructor, which writes nothing. What
          // depends on the discretisation (the vesicle fits the box) is
          // checked when the study runs.
          const std::string study_name = prm.get("Study");
          for (const auto &s : available_studies())
            if (s.name == study_name)
              s.create(prm, context);
          pcout << name << ": valid parameters for study " << study_name
                << ", dimension " << context.dimension << std::endl;
          return 0;
        }

      const auto lock = prepare_output_directory(prm, context);

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


    /**
     * One rank failed: if every rank fails with it (an input error, a
     * failed step: all see the same numbers), rank 0 reports it and all
     * return 1. If the others do not join within 5 seconds (they wait in a
     * collective, or compute), this rank reports its own message and ends
     * the whole job: a run never hangs with one failed rank.
     */
    int
    fail(const std::string &message, const MPI_Comm error_comm)
    {
      const unsigned int rank    = Utilities::MPI::this_mpi_process(error_comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(error_comm);
      if (n_ranks > 1)
        {
          MPI_Request request;
          MPI_Ibarrier(error_comm, &request);
          int        done  = 0;
          const auto start = std::chrono::steady_clock::now();
          while (!done
                 && std::chrono::steady_clock::now() - start
                      < std::chrono::seconds(5))
            {
              MPI_Test(&request, &done, MPI_STATUS_IGNORE);
              if (!done)
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
          if (!done)
            {
              std::cerr << "vesicle-iga: error on rank " << rank
                        << " (the other ranks continued; the job is ended): "
                        << message << std::endl;
              MPI_Abort(MPI_COMM_WORLD, 1);
            }
        }
      if (rank == 0)
        std::cerr << "vesicle-iga: error: " << message << std::endl;
      return 1;
    }
  } // namespace


  int
  run_program(const std::vector<std::string> &args)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    ConditionalOStream pcout(std::cout, root);
    // A write beyond a file-size limit then fails (and is reported) instead
    // of killing the process; HDF5 errors are reported by the checks of
    // io/checkpoint.cc, without HDF5's own traces.
    std::signal(SIGXFSZ, SIG_IGN);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    MPI_Comm error_comm;
    MPI_Comm_dup(comm, &error_comm);
    int code = 1;
    try
      {
        code = run_arguments(args, comm, pcout);
      }
    catch (const RunInterrupted &e)
      {
        if (root)
          std::cerr << "vesicle-iga: " << e.what() << std::endl;
        code = 3;
      }
    catch (const ExceptionBase &e)
      {
        code = fail(describe(e), error_comm);
      }
    catch (const std::exception &e)
      {
        code = fail(e.what(), error_comm);
      }
    catch (...)
      {
        code = fail("an exception of unknown type", error_comm);
      }
    MPI_Comm_free(&error_comm);
    return code;
  }
} // namespace vesicle_iga
