#include <deal.II/base/hdf5.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>

#include <cstdio>
#include <fstream>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    std::string
    join(const std::vector<std::string> &names)
    {
      std::string s;
      for (const auto &n : names)
        s += (s.empty() ? "" : ",") + n;
      return s;
    }
  } // namespace


  void
  Checkpoint::write(const std::string &filename, const MPI_Comm comm) const
  {
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string tmp  = filename + ".tmp";
    {
      HDF5::File file(tmp, HDF5::File::FileAccessMode::create, comm);
      std::vector<std::string> vector_names, scalar_names;
      for (const auto &[name, v] : vectors)
        {
          // Sizes are taken from rank 0 so that every rank creates the same
          // dataset (the collective call needs identical arguments).
          const unsigned long long n
            = Utilities::MPI::broadcast(comm, (unsigned long long)v.size(), 0);
          auto dataset
            = file.create_dataset<double>(name, std::vector<hsize_t>{n});
          if (root)
            dataset.write(v);
          else
            dataset.write_none<double>();
          vector_names.push_back(name);
        }
      for (const auto &[name, value] : scalars)
        {
          file.set_attribute(name, value);
          scalar_names.push_back(name);
        }
      file.set_attribute("vector_names", join(vector_names));
      file.set_attribute("scalar_names", join(scalar_names));
    }
    MPI_Barrier(comm);
    if (root)
      std::rename(tmp.c_str(), filename.c_str());
    MPI_Barrier(comm);
  }


  Checkpoint
  Checkpoint::read(const std::string &filename, const MPI_Comm comm)
  {
    check_input(static_cast<bool>(std::ifstream(filename)),
                "Restart from",
                filename,
                "a checkpoint file written by a previous run");
    Checkpoint c;
    c.source = filename;
    try
      {
        HDF5::File file(filename, HDF5::File::FileAccessMode::open, comm);
        for (const auto &name : Utilities::split_string_list(
               file.get_attribute<std::string>("vector_names"), ','))
          c.vectors[name] = file.open_dataset(name).read<std::vector<double>>();
        for (const auto &name : Utilities::split_string_list(
               file.get_attribute<std::string>("scalar_names"), ','))
          c.scalars[name] = file.get_attribute<double>(name);
      }
    catch (...)
      {
        throw InputError("Restart from",
                         filename,
                         "a complete checkpoint of this version of the "
                         "program (missing or unreadable datasets)");
      }
    return c;
  }


  const std::vector<double> &
  Checkpoint::vector(const std::string &name) const
  {
    const auto it = vectors.find(name);
    check_input(it != vectors.end(),
                "Restart from",
                source,
                "a checkpoint of this study (it has no vector '" + name + "')");
    return it->second;
  }


  double
  Checkpoint::scalar(const std::string &name) const
  {
    const auto it = scalars.find(name);
    check_input(it != scalars.end(),
                "Restart from",
                source,
                "a checkpoint of this study (it has no value '" + name + "')");
    return it->second;
  }
} // namespace vesicle_iga
