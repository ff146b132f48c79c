#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/io/time_series.h>

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace vesicle_iga
{
  using namespace dealii;

  TimeSeriesWriter::TimeSeriesWriter(const std::string              &filename,
                                     const std::vector<std::string> &columns,
                                     const MPI_Comm communicator,
                                     const long     restart_step)
    : names(columns)
    , filename(filename)
    , communicator(communicator)
  {
    bool ok = true;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      ok = start(restart_step);
    ok = dealii::Utilities::MPI::min(int(ok), communicator);
    AssertThrow(ok,
                dealii::ExcMessage("cannot write " + filename
                                   + " (no permission, disk full or quota?)"));
  }


  bool
  TimeSeriesWriter::start(const long restart_step)
  {
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
          {
            // Only complete rows (a killed run may have cut the last one).
            const auto fields = dealii::Utilities::split_string_list(line, ',');
            bool       complete = fields.size() == old_names.size();
            long       step     = -1;
            try
              {
                for (const auto &f : fields)
                  (void)std::stod(f);
                step = std::stol(fields.at(0));
              }
            catch (...)
              {
                complete = false;
              }
            if (!complete || step > restart_step)
              continue;
            if (old_names == names)
              {
                kept.push_back(line);
                continue;
              }
            std::string row;
            for (unsigned int i = 0; i < names.size(); ++i)
              row += (i ? "," : "")
                     + (source[i] >= 0 && source[i] < int(fields.size()) ?
                          fields[source[i]] :
                          std::string("nan"));
            kept.push_back(row);
          }
      }
    // Header and kept rows through a temporary file: a run killed now still
    // has the old file.
    {
      std::ofstream tmp(filename + ".tmp");
      for (unsigned int i = 0; i < names.size(); ++i)
        tmp << (i ? "," : "") << names[i];
      tmp << '\n';
      for (const auto &line : kept)
        tmp << line << '\n';
      tmp.flush();
      if (!tmp)
        return false;
    }
    if (std::rename((filename + ".tmp").c_str(), filename.c_str()) != 0)
      return false;
    file.open(filename, std::ios::app);
    file << std::setprecision(12);
    return static_cast<bool>(file);
  }


  void
  TimeSeriesWriter::add_row(const std::vector<double> &values)
  {
    Assert(values.size() == names.size(),
           dealii::ExcDimensionMismatch(values.size(), names.size()));
    bool ok = true;
    if (file.is_open())
      {
        std::ostringstream row;
        row << std::setprecision(12) << static_cast<long>(values[0]);
        for (unsigned int i = 1; i < values.size(); ++i)
          row << ',' << values[i];
        row << '\n';
        const std::string text = row.str();
        if (fault_requested("series-write"))
          {
            file << text.substr(0, text.size() / 2) << std::flush;
            kill_process();
          }
        file << text << std::flush;
        ok = static_cast<bool>(file);
      }
    // Every rank learns whether rank 0 could write.
    ok = dealii::Utilities::MPI::min(int(ok), communicator);
    AssertThrow(ok,
                dealii::ExcMessage(
                  "cannot write " + filename
                  + " (no permission, disk full, quota or file size limit?)"));
  }
} // namespace vesicle_iga
