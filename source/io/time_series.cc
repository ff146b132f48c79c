#include <deal.II/base/exceptions.h>

#include <vesicle_iga/io/time_series.h>

#include <iomanip>

namespace vesicle_iga
{
  TimeSeriesWriter::TimeSeriesWriter(const std::string              &filename,
                                     const std::vector<std::string> &columns,
                                     const MPI_Comm communicator,
                                     const long     restart_step)
    : names(columns)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::vector<std::string> kept;
    if (restart_step >= 0)
      {
        std::ifstream old(filename);
        std::string   line;
        while (std::getline(old, line))
          if (kept.empty()
              || std::stol(line.substr(0, line.find(','))) <= restart_step)
            kept.push_back(line);
      }
    file.open(filename);
    AssertThrow(file, dealii::ExcMessage("Cannot write " + filename));
    if (kept.empty())
      {
        for (unsigned int i = 0; i < names.size(); ++i)
          file << (i ? "," : "") << names[i];
        file << '\n';
      }
    for (const auto &line : kept)
      file << line << '\n';
    file << std::setprecision(12) << std::flush;
  }


  void
  TimeSeriesWriter::add_row(const std::vector<double> &values)
  {
    Assert(values.size() == names.size(),
           dealii::ExcDimensionMismatch(values.size(), names.size()));
    if (!file.is_open())
      return;
    file << static_cast<long>(values[0]);
    for (unsigned int i = 1; i < values.size(); ++i)
      file << ',' << values[i];
    file << std::endl;
  }
} // namespace vesicle_iga
