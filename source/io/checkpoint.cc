#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <hdf5.h>
#include <set>
#include <stdexcept>
#include <unistd.h>

namespace vesicle_iga
{
  using namespace dealii;

  namespace
  {
    /// An HDF5 identifier closed by its own close function; an identifier
    /// below zero is an error of the call that made it.
    class Handle
    {
    public:
      Handle(const hid_t id, herr_t (*close)(hid_t), const std::string &what)
        : id(id)
        , close_function(close)
      {
        if (id < 0)
          throw std::runtime_error(what);
      }
      Handle(const Handle &) = delete;
      Handle &
      operator=(const Handle &)
        = delete;
      ~Handle()
      {
        if (id >= 0)
          close_function(id);
      }
      /// Close now and report whether HDF5 could (a full disk shows here,
      /// when the file's last blocks are written).
      bool
      close()
      {
        const herr_t status = close_function(id);
        id                  = -1;
        return status >= 0;
      }
      operator hid_t() const
      {
        return id;
      }

    private:
      hid_t id;
      herr_t (*close_function)(hid_t);
    };

    void
    check(const herr_t status, const std::string &what)
    {
      if (status < 0)
        throw std::runtime_error(what);
    }

    std::string
    join(const std::vector<std::string> &names)
    {
      std::string s;
      for (const auto &n : names)
        s += (s.empty() ? "" : ",") + n;
      return s;
    }

    void
    write_string_attribute(const hid_t        file,
                           const std::string &name,
                           const std::string &value)
    {
      Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
      check(H5Tset_size(type, std::max<std::size_t>(value.size(), 1)),
            "string size");
      Handle space(H5Screate(H5S_SCALAR), H5Sclose, "attribute space");
      Handle attribute(
        H5Acreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose,
        "attribute " + name);
      std::string padded = value.empty() ? std::string(1, '\0') : value;
      check(H5Awrite(attribute, type, padded.data()), "attribute " + name);
    }

    std::string
    read_string_attribute(const hid_t file, const std::string &name)
    {
      Handle      attribute(H5Aopen(file, name.c_str(), H5P_DEFAULT),
                       H5Aclose,
                       "it has no index '" + name + "' (incomplete file)");
      Handle      type(H5Aget_type(attribute), H5Tclose, "attribute type");
      std::string value(H5Tget_size(type), '\0');
      check(H5Aread(attribute, type, value.data()),
            "the index '" + name + "' cannot be read");
      return value.substr(0, value.find('\0'));
    }

    void
    write_double_attribute(const hid_t        file,
                           const std::string &name,
                           const double       value)
    {
      Handle space(H5Screate(H5S_SCALAR), H5Sclose, "attribute space");
      Handle attribute(H5Acreate2(file,
                                  name.c_str(),
                                  H5T_NATIVE_DOUBLE,
                                  space,
                                  H5P_DEFAULT,
                                  H5P_DEFAULT),
                       H5Aclose,
                       "attribute " + name);
      check(H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value),
            "attribute " + name);
    }

    double
    read_double_attribute(const hid_t file, const std::string &name)
    {
      Handle attribute(H5Aopen(file, name.c_str(), H5P_DEFAULT),
                       H5Aclose,
                       "its value '" + name + "' is missing");
      double value = 0;
      check(H5Aread(attribute, H5T_NATIVE_DOUBLE, &value),
            "its value '" + name + "' cannot be read");
      return value;
    }

    void
    write_dataset(const hid_t                file,
                  const std::string         &name,
                  const std::vector<double> &v)
    {
      const hsize_t n = v.size();
      Handle        space(H5Screate_simple(1, &n, nullptr),
                   H5Sclose,
                   "dataspace of " + name);
      Handle        dataset(H5Dcreate2(file,
                                name.c_str(),
                                H5T_NATIVE_DOUBLE,
                                space,
                                H5P_DEFAULT,
                                H5P_DEFAULT,
                                H5P_DEFAULT),
                     H5Dclose,
                     "dataset " + name);
      if (n > 0)
        check(H5Dwrite(dataset,
                       H5T_NATIVE_DOUBLE,
                       H5S_ALL,
                       H5S_ALL,
                       H5P_DEFAULT,
                       v.data()),
              "dataset " + name);
    }

    std::vector<double>
    read_dataset(const hid_t file, const std::string &name)
    {
      Handle  dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT),
                     H5Dclose,
                     "its vector '" + name + "' is missing");
      Handle  space(H5Dget_space(dataset), H5Sclose, "dataspace of " + name);
      hsize_t n = 0;
      if (H5Sget_simple_extent_ndims(space) != 1)
        throw std::runtime_error("its vector '" + name + "' is not a vector");
      H5Sget_simple_extent_dims(space, &n, nullptr);
      std::vector<double> v(n);
      if (n > 0)
        check(H5Dread(dataset,
                      H5T_NATIVE_DOUBLE,
                      H5S_ALL,
                      H5S_ALL,
                      H5P_DEFAULT,
                      v.data()),
              "its vector '" + name + "' cannot be read (truncated file?)");
      return v;
    }
  } // namespace


  std::vector<char>
  Checkpoint::file_image() const
  {
    // The HDF5 file is built in memory (core driver, no backing store) and
    // written by write_file: HDF5 then never meets a failing write, which
    // it cannot recover from (a file it cannot flush stays open in the
    // library until exit).
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
    check(H5Pset_fapl_core(access, 1 << 20, 0), "in-memory file");
    Handle file(
      H5Fcreate("checkpoint-in-memory.h5", H5F_ACC_TRUNC, H5P_DEFAULT, access),
      H5Fclose,
      "the in-memory file cannot be created");
    std::vector<std::string> vector_names, field_names, scalar_names;
    for (const auto &[name, v] : vectors)
      {
        write_dataset(file, name, v);
        vector_names.push_back(name);
      }
    for (const auto &[name, v] : fields)
      {
        write_dataset(file, name, v);
        field_names.push_back(name);
      }
    for (const auto &[name, value] : scalars)
      {
        write_double_attribute(file, name, value);
        scalar_names.push_back(name);
      }
    // The index last: a file without it was not completed.
    write_string_attribute(file, "vector_names", join(vector_names));
    write_string_attribute(file, "field_names", join(field_names));
    write_string_attribute(file, "scalar_names", join(scalar_names));
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush of the in-memory file");
    const ssize_t size = H5Fget_file_image(file, nullptr, 0);
    if (size <= 0)
      throw std::runtime_error("the in-memory file has no image");
    std::vector<char> image(size);
    if (H5Fget_file_image(file, image.data(), image.size()) != size)
      throw std::runtime_error("the in-memory file image cannot be copied");
    return image;
  }


  void
  Checkpoint::write_file(const std::string &filename) const
  {
    const std::vector<char> image = file_image();
    const int fd = ::open(filename.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0644);
    if (fd < 0)
      throw std::runtime_error("the file cannot be created ("
                               + std::string(std::strerror(errno)) + ")");
    // Test fault: killed with half of the file written.
    const std::size_t end
      = fault_requested("checkpoint-write") ? image.size() / 2 : image.size();
    std::size_t written = 0;
    while (written < end)
      {
        const ssize_t n = ::write(fd, image.data() + written, end - written);
        if (n <= 0)
          {
            const std::string reason = std::strerror(errno);
            ::close(fd);
            throw std::runtime_error(
              "writing failed after " + std::to_string(written) + " of "
              + std::to_string(image.size()) + " bytes (" + reason + ")");
          }
        written += n;
      }
    if (end < image.size())
      kill_process();
    // On disk before the rename, so that a crash of the machine cannot
    // leave a renamed but empty file.
    const bool synced = ::fsync(fd) == 0;
    const bool closed = ::close(fd) == 0;
    if (!synced || !closed)
      throw std::runtime_error("the file cannot be completed ("
                               + std::string(std::strerror(errno)) + ")");
  }


  void
  Checkpoint::write(const std::string &filename, const MPI_Comm comm) const
  {
    // Rank 0 holds the complete fields and writes alone (serial HDF5): a
    // failure is then its own to report, never a collective HDF5 call that
    // the other ranks wait in. The file is written as "<file>.tmp", read
    // back and renamed: a run killed while writing keeps the previous
    // checkpoint, and a file that does not read back is never renamed.
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string tmp = filename + ".tmp";
        try
          {
            write_file(tmp);
            const Checkpoint back = read_file(tmp);
            if (back.vectors.size() != vectors.size()
                || back.fields.size() != fields.size()
                || back.scalars != scalars)
              throw std::runtime_error("it does not read back as written");
            for (const auto &[name, v] : vectors)
              if (back.vectors.at(name).size() != v.size())
                throw std::runtime_error("vector '" + name
                                         + "' does not read back");
            for (const auto &[name, v] : fields)
              if (back.fields.at(name).size() != v.size())
                throw std::runtime_error("field '" + name
                                         + "' does not read back");
            if (std::rename(tmp.c_str(), filename.c_str()) != 0)
              throw std::runtime_error("it cannot be renamed to " + filename);
          }
        catch (const std::exception &e)
          {
            std::remove(tmp.c_str());
            error = "cannot write the checkpoint " + filename + ": " + e.what()
                    + " (no permission, disk full, quota or file size "
                      "limit?); the previous checkpoint, if any, is kept";
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
  }


  Checkpoint
  Checkpoint::read_file(const std::string &filename)
  {
    Checkpoint c;
    c.source = filename;
    {
      std::ifstream exists(filename);
      if (!exists)
        throw std::runtime_error("the file does not exist or cannot be read");
    }
    if (H5Fis_hdf5(filename.c_str()) <= 0)
      throw std::runtime_error("it is not an HDF5 file");
    Handle file(H5Fopen(filename.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                H5Fclose,
                "HDF5 cannot open it (truncated or damaged file?)");
    for (const auto &name : Utilities::split_string_list(
           read_string_attribute(file, "vector_names"), ','))
      c.vectors[name] = read_dataset(file, name);
    // Files of format 2 and 3 have no fields: theirs are vectors.
    if (H5Aexists(file, "field_names") > 0)
      for (const auto &name : Utilities::split_string_list(
             read_string_attribute(file, "field_names"), ','))
        c.fields[name] = read_dataset(file, name);
    for (const auto &name : Utilities::split_string_list(
           read_string_attribute(file, "scalar_names"), ','))
      c.scalars[name] = read_double_attribute(file, name);
    return c;
  }


  Checkpoint
  Checkpoint::read(const std::string &filename, const MPI_Comm comm)
  {
    // Rank 0 reads and sends all but the fields: every rank then agrees on
    // success or on the one message.
    std::string error;
    Checkpoint  c;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          c = read_file(filename);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    check_input(error.empty(),
                "Restart from",
                filename,
                "a complete checkpoint.h5 written by this program (" + error
                  + ")");
    for (const auto &[name, v] : c.fields)
      c.field_sizes[name] = v.size();
    c.field_sizes = Utilities::MPI::broadcast(comm, c.field_sizes, 0);
    c.vectors     = Utilities::MPI::broadcast(comm, c.vectors, 0);
    c.scalars     = Utilities::MPI::broadcast(comm, c.scalars, 0);
    c.source      = filename;
    return c;
  }


  std::string
  Checkpoint::contents() const
  {
    std::set<std::string> prefixes;
    for (const auto &[name, v] : vectors)
      prefixes.insert(name.substr(0, name.find('.')));
    for (const auto &[name, size] : field_sizes)
      prefixes.insert(name.substr(0, name.find('.')));
    std::string s;
    for (const auto &p : prefixes)
      s += (s.empty() ? "" : ", ") + p + ".*";
    return s.empty() ? "nothing" : s;
  }


  const std::vector<double> &
  Checkpoint::vector(const std::string &name) const
  {
    const auto it = vectors.find(name);
    check_input(it != vectors.end(),
                "Restart from",
                source,
                "a checkpoint of this kind of study: it has no vector '" + name
                  + "' (it holds the vectors " + contents()
                  + ": a checkpoint of another study?)");
    return it->second;
  }


  double
  Checkpoint::scalar(const std::string &name) const
  {
    const auto it = scalars.find(name);
    check_input(it != scalars.end(),
                "Restart from",
                source,
                "a checkpoint of this kind of study: it has no value '" + name
                  + "' (it holds the vectors " + contents()
                  + ": a checkpoint of another study?)");
    return it->second;
  }
} // namespace vesicle_iga
