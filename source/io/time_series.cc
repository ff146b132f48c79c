#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/io/time_series.h>

#include <iomanip>

namespace vesicle_iga
{
  using namespace dealii;

  TimeSeriesWriter::TimeSeriesWriter(const std::string              &filename,
                                     const std::vector<std::string> &columns,
                                     const MPI_Comm communicator,
                                     const long     restart_step)
    : names(columns)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    // On restart the rows up to the restart step are kept. A file written
    // by a version with other columns (e.g. before a column was added) is
    // rewritten in the new columns, matched by name; a column the old file
    // lacks is "nan" in its rows.
    std::vector<std::string> kept;
    if (restart_step >= 0)
      {
        std::ifstream            old(filename);
        std::string              line;
        std::vector<std::string> old_names;
        if (std::getline(old, line))
          old_names = dealii::Utilities::split_string_list(line, ',');
        std::vector<int> source(names.size(), -1);
        for (unsigned int i = 0; i < names.size(); ++i)
          for (unsigned int j = 0; j < old_names.size(); ++j)
            if (old_names[j] == names[i])
              source[i] = j;
        while (std::getline(old, line))
          if (std::stol(line.substr(0, line.find(','))) <= restart_step)
            {
              if (old_names == names)
                {
                  kept.push_back(line);
                  continue;
                }
              const auto fields
                = dealii::Utilities::split_string_list(line, ',');
              std::string row;
              for (unsigned int i = 0; i < names.size(); ++i)
                row += (i ? "," : "")
                       + (source[i] >= 0 && source[i] < int(fields.size()) ?
                            fields[source[i]] :
                            std::string("nan"));
              kept.push_back(row);
            }
      }
    file.open(filename);
    AssertThrow(file, dealii::ExcMessage("Cannot write " + filename));
    for (unsigned int i = 0; i < names.size(); ++i)
      file << (i ? "," : "") << names[i];
    file << '\n';
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
