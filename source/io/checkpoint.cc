#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <vesicle_iga/base/fault_injection.h>
#include <vesicle_iga/base/input_error.h>
#include <vesicle_iga/io/checkpoint.h>

#include <algorithm>
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

    /// The number of entries of the one-dimensional dataset @p name (a
    /// "vector" or "field" of the checkpoint, for messages).
    std::uint64_t
    dataset_length(const hid_t        file,
                   const std::string &name,
                   const std::string &kind)
    {
      Handle  dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT),
                     H5Dclose,
                     "its " + kind + " '" + name + "' is missing");
      Handle  space(H5Dget_space(dataset), H5Sclose, "dataspace of " + name);
      hsize_t n = 0;
      if (H5Sget_simple_extent_ndims(space) != 1)
        throw std::runtime_error("its " + kind + " '" + name
                                 + "' is not a vector");
      H5Sget_simple_extent_dims(space, &n, nullptr);
      return n;
    }

    std::vector<double>
    read_dataset(const hid_t file, const std::string &name)
    {
      std::vector<double> v(dataset_length(file, name, "vector"));
      Handle              dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT),
                     H5Dclose,
                     "its vector '" + name + "' is missing");
      if (!v.empty())
        check(H5Dread(dataset,
                      H5T_NATIVE_DOUBLE,
                      H5S_ALL,
                      H5S_ALL,
                      H5P_DEFAULT,
                      v.data()),
              "its vector '" + name + "' cannot be read (truncated file?)");
      return v;
    }

    /// The storage of a field of @p n values: contiguous, allocated when
    /// created, never filled (the ranks write it); returns its file offset.
    std::uint64_t
    allocate_field(const hid_t file, const std::string &name, const hsize_t n)
    {
      Handle space(H5Screate_simple(1, &n, nullptr),
                   H5Sclose,
                   "dataspace of " + name);
      Handle properties(H5Pcreate(H5P_DATASET_CREATE),
                        H5Pclose,
                        "creation properties of " + name);
      check(H5Pset_layout(properties, H5D_CONTIGUOUS), "layout of " + name);
      check(H5Pset_alloc_time(properties, H5D_ALLOC_TIME_EARLY),
            "allocation of " + name);
      check(H5Pset_fill_time(properties, H5D_FILL_TIME_NEVER),
            "fill of " + name);
      Handle dataset(H5Dcreate2(file,
                                name.c_str(),
                                H5T_IEEE_F64LE,
                                space,
                                H5P_DEFAULT,
                                properties,
                                H5P_DEFAULT),
                     H5Dclose,
                     "dataset " + name);
      if (n == 0)
        return 0;
      const haddr_t offset = H5Dget_offset(dataset);
      if (offset == HADDR_UNDEF)
        throw std::runtime_error("the storage of field " + name
                                 + " has no file offset");
      return offset;
    }

    /// Writes all of @p size bytes at @p offset of @p fd.
    void
    write_at(const int           fd,
             const char         *data,
             const std::size_t   size,
             const std::uint64_t offset)
    {
      std::size_t written = 0;
      while (written < size)
        {
          const ssize_t n
            = ::pwrite(fd, data + written, size - written, offset + written);
          if (n <= 0)
            throw std::runtime_error("writing failed at byte "
                                     + std::to_string(offset + written) + " ("
                                     + std::strerror(errno) + ")");
          written += n;
        }
    }

    /// Makes what was written durable and closes @p fd.
    void
    sync_and_close(const int fd)
    {
      // On disk before the rename, so that a crash of the machine cannot
      // leave a renamed but empty file.
      const bool synced = ::fsync(fd) == 0;
      const bool closed = ::close(fd) == 0;
      if (!synced || !closed)
        throw std::runtime_error("the file cannot be completed ("
                                 + std::string(std::strerror(errno)) + ")");
    }

    /// The message of the lowest rank that has one, on every rank.
    std::string
    first_error(const MPI_Comm comm, const std::string &local)
    {
      const unsigned int none    = numbers::invalid_unsigned_int;
      const unsigned int failing = Utilities::MPI::min(
        local.empty() ? none : Utilities::MPI::this_mpi_process(comm), comm);
      if (failing == none)
        return {};
      return Utilities::MPI::broadcast(comm, local, failing);
    }
  } // namespace


  std::map<std::string, std::uint64_t>
  Checkpoint::write_layout(const std::string &filename) const
  {
    // The values are written as raw little-endian doubles by every rank.
    if (H5Tequal(H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE) <= 0)
      throw std::runtime_error("checkpoints need IEEE little-endian doubles");
    // The HDF5 file is built in memory (core driver, no backing store) and
    // written below: HDF5 then never meets a failing write, which it cannot
    // recover from (a file it cannot flush stays open in the library until
    // exit). The fields' storage is allocated in it but not written.
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
    std::map<std::string, std::uint64_t>                 offsets;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> storage;
    for (const auto &[name, part] : fields)
      {
        offsets[name] = allocate_field(file, name, part.size);
        if (part.size > 0)
          storage.emplace_back(offsets[name],
                               offsets[name] + sizeof(double) * part.size);
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

    // Everything but the fields' storage, which stays a hole until the
    // ranks fill it.
    std::sort(storage.begin(), storage.end());
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pieces;
    std::uint64_t                                        begin = 0;
    for (const auto &[first, last] : storage)
      {
        if (first > begin)
          pieces.emplace_back(begin, first);
        begin = std::max(begin, last);
      }
    if (begin < image.size())
      pieces.emplace_back(begin, image.size());

    const int fd = ::open(filename.c_str(), O_CREAT | O_TRUNC | O_WRONLY, 0644);
    if (fd < 0)
      throw std::runtime_error("the file cannot be created ("
                               + std::string(std::strerror(errno)) + ")");
    try
      {
        // Test fault: killed with half of the file's metadata written.
        const bool killed = fault_requested("checkpoint-write");
        for (std::size_t k = 0; k < pieces.size(); ++k)
          {
            const auto [first, last] = pieces[k];
            const std::size_t length
              = killed && k == 0 ? (last - first) / 2 : last - first;
            write_at(fd, image.data() + first, length, first);
            if (killed)
              kill_process();
          }
        if (::ftruncate(fd, image.size()) != 0)
          throw std::runtime_error("the file cannot be extended to "
                                   + std::to_string(image.size()) + " bytes ("
                                   + std::strerror(errno) + ")");
      }
    catch (...)
      {
        ::close(fd);
        throw;
      }
    sync_and_close(fd);
    return offsets;
  }


  void
  Checkpoint::write_field_parts(
    const std::string                          &filename,
    const std::map<std::string, std::uint64_t> &offsets) const
  {
    const int fd = ::open(filename.c_str(), O_WRONLY);
    if (fd < 0)
      throw std::runtime_error("the file cannot be opened for the fields ("
                               + std::string(std::strerror(errno)) + ")");
    try
      {
        for (const auto &[name, part] : fields)
          {
            const auto &index = part.natural_indices;
            if (index.size() != part.values.size()
                || (!index.empty() && index.back() >= part.size))
              throw std::runtime_error("field '" + name
                                       + "' has entries outside it");
            // One write per run of consecutive natural indices.
            for (std::size_t k = 0; k < index.size();)
              {
                std::size_t end = k + 1;
                while (end < index.size() && index[end] == index[end - 1] + 1)
                  ++end;
                write_at(fd,
                         reinterpret_cast<const char *>(&part.values[k]),
                         sizeof(double) * (end - k),
                         offsets.at(name) + sizeof(double) * index[k]);
                k = end;
              }
          }
      }
    catch (...)
      {
        ::close(fd);
        throw;
      }
    sync_and_close(fd);
  }


  void
  Checkpoint::write(const std::string &filename, const MPI_Comm comm) const
  {
    // Rank 0 lays the file out, then every rank writes its own entries of
    // the fields. The file is written as "<file>.tmp", its index read back
    // and renamed: a run killed while writing keeps the previous
    // checkpoint, and a file that does not read back is never renamed.
    // Every failure is one rank's, reported to all by messages, never
    // inside a collective I/O call.
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string tmp  = filename + ".tmp";
    std::string       error;
    std::map<std::string, std::uint64_t> offsets;
    if (root)
      try
        {
          offsets = write_layout(tmp);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (error.empty())
      {
        offsets = Utilities::MPI::broadcast(comm, offsets, 0);
        std::string local;
        try
          {
            write_field_parts(tmp, offsets);
          }
        catch (const std::exception &e)
          {
            local = e.what();
          }
        error = first_error(comm, local);
      }
    if (root && error.empty())
      try
        {
          const Checkpoint back = read_file(tmp);
          if (back.vectors.size() != vectors.size()
              || back.fields.size() != fields.size() || back.scalars != scalars)
            throw std::runtime_error("it does not read back as written");
          for (const auto &[name, v] : vectors)
            if (back.vectors.at(name).size() != v.size())
              throw std::runtime_error("vector '" + name
                                       + "' does not read back");
          for (const auto &[name, part] : fields)
            if (back.fields.at(name).size != part.size)
              throw std::runtime_error("field '" + name
                                       + "' does not read back");
          if (std::rename(tmp.c_str(), filename.c_str()) != 0)
            throw std::runtime_error("it cannot be renamed to " + filename);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    if (root && !error.empty())
      std::remove(tmp.c_str());
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw std::runtime_error("cannot write the checkpoint " + filename + ": "
                               + error
                               + " (no permission, disk full, quota or file "
                                 "size limit?); the previous checkpoint, if "
                                 "any, is kept");
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
        c.fields[name].size = dataset_length(file, name, "field");
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
    std::map<std::string, std::uint64_t> sizes;
    for (const auto &[name, part] : c.fields)
      sizes[name] = part.size;
    sizes = Utilities::MPI::broadcast(comm, sizes, 0);
    for (const auto &[name, size] : sizes)
      c.fields[name].size = size;
    c.vectors = Utilities::MPI::broadcast(comm, c.vectors, 0);
    c.scalars = Utilities::MPI::broadcast(comm, c.scalars, 0);
    c.source  = filename;
    return c;
  }


  std::vector<double>
  Checkpoint::read_field(const std::string                &name,
                         const std::vector<std::uint64_t> &natural_indices,
                         const MPI_Comm                    comm) const
  {
    std::vector<double> values(natural_indices.size());
    std::string         error;
    try
      {
        const std::uint64_t size = fields.at(name).size;
        for (const auto i : natural_indices)
          if (i >= size)
            throw std::runtime_error("field '" + name + "' has "
                                     + std::to_string(size) + " entries");
        if (!natural_indices.empty())
          {
            Handle file(H5Fopen(source.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                        H5Fclose,
                        "HDF5 cannot open it (truncated or damaged file?)");
            Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT),
                           H5Dclose,
                           "its field '" + name + "' is missing");
            Handle file_space(H5Dget_space(dataset),
                              H5Sclose,
                              "dataspace of " + name);
            const std::vector<hsize_t> points(natural_indices.begin(),
                                              natural_indices.end());
            check(H5Sselect_elements(
                    file_space, H5S_SELECT_SET, points.size(), points.data()),
                  "selection in field '" + name + "'");
            const hsize_t n = points.size();
            Handle        memory_space(H5Screate_simple(1, &n, nullptr),
                                H5Sclose,
                                "memory space of " + name);
            check(H5Dread(dataset,
                          H5T_NATIVE_DOUBLE,
                          memory_space,
                          file_space,
                          H5P_DEFAULT,
                          values.data()),
                  "its field '" + name + "' cannot be read (truncated file?)");
          }
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    error = first_error(comm, error);
    check_input(error.empty(),
                "Restart from",
                source,
                "a complete checkpoint.h5 written by this program (" + error
                  + ")");
    return values;
  }


  std::string
  Checkpoint::contents() const
  {
    std::set<std::string> prefixes;
    for (const auto &[name, v] : vectors)
      prefixes.insert(name.substr(0, name.find('.')));
    for (const auto &[name, part] : fields)
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
