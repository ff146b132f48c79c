#pragma once

#include <deal.II/base/mpi.h>

#include <map>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * A checkpoint: named fields (spline coefficients in the natural numbering
   * of the spline basis, so that a run can restart on any number of ranks),
   * named small vectors and named scalars, stored as an HDF5 file (datasets
   * and attributes, with an index of the names written last). The fields
   * are complete on rank 0 only, which writes and reads the file: no other
   * rank ever holds a whole field (save_field() and load_field() gather and
   * scatter them). Writing goes to "<file>.tmp", is read
   * back and renamed when complete, so a run killed while writing still has
   * its previous checkpoint and a half-written file is never read. Names
   * are "<prefix>.<name>": every stateful object saves and loads itself
   * under its prefix (Checkpointable).
   */
  struct Checkpoint
  {
    /// Small vectors, the same on every rank (per-vesicle values).
    std::map<std::string, std::vector<double>> vectors;
    std::map<std::string, double>              scalars;
    /// The fields: complete on rank 0, empty on the other ranks.
    std::map<std::string, std::vector<double>> fields;
    /// The length of every field, known on every rank.
    std::map<std::string, std::size_t> field_sizes;

    /// Collective; the vectors must be complete on rank 0, which writes.
    /// Throws (on every rank) a message naming the file if it cannot be
    /// written; the previous file is then left as it was.
    void
    write(const std::string &filename, const MPI_Comm comm) const;
    /// Collective; rank 0 reads and keeps the fields, every rank gets the
    /// scalars, the small vectors and the field sizes. A file written
    /// before fields were told apart (format 2 and 3) holds its fields as
    /// vectors, which every rank then gets. Throws
    /// InputError naming "Restart from" and what is wrong with the file
    /// (missing, not HDF5, truncated, incomplete).
    static Checkpoint
    read(const std::string &filename, const MPI_Comm comm);

    /// The entries; InputError naming "Restart from" and the entry if the
    /// checkpoint lacks it (a checkpoint of another study or version).
    const std::vector<double> &
    vector(const std::string &name) const;
    double
    scalar(const std::string &name) const;
    /// Whether @p name was stored as a field (else: an older file).
    bool
    has_field(const std::string &name) const
    {
      return field_sizes.count(name) > 0;
    }

    /// The file read (for messages).
    std::string source;

  private:
    /// The HDF5 file, built in memory.
    std::vector<char>
    file_image() const;
    void
    write_file(const std::string &filename) const;
    static Checkpoint
    read_file(const std::string &filename);
    /// The prefixes of the vectors, for messages ("flow.*").
    std::string
    contents() const;
  };


  /**
   * An object whose state a restart needs: it writes and reads its own
   * entries under a prefix, so that their names are listed in one place.
   */
  class Checkpointable
  {
  public:
    virtual ~Checkpointable() = default;
    virtual void
    save(Checkpoint &checkpoint, const std::string &prefix) const = 0;
    virtual void
    load(const Checkpoint &checkpoint, const std::string &prefix)
      = 0;
  };
} // namespace vesicle_iga
