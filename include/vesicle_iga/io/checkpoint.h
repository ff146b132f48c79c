#pragma once

#include <deal.II/base/mpi.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * The part of a field that one rank holds: spline coefficients in the
   * natural numbering of the spline basis (so that a run can restart on any
   * number of ranks), by their natural index.
   */
  struct FieldPart
  {
    /// The length of the whole field, the same on every rank.
    std::uint64_t size = 0;
    /// Ascending natural indices of the entries this rank holds.
    std::vector<std::uint64_t> natural_indices;
    std::vector<double>        values;
  };


  /**
   * A checkpoint: named fields, named small vectors and named scalars,
   * stored as an HDF5 file (datasets and attributes, with an index of the
   * names written last). Names are "<prefix>.<name>": every stateful object
   * saves and loads itself under its prefix (Checkpointable).
   *
   * No rank ever holds a whole field. Writing is parallel: rank 0 lays out
   * the file (its HDF5 metadata, the small vectors and the scalars, with the
   * storage of every field allocated contiguously), then every rank writes
   * its own entries of every field into that storage, at their natural
   * indices. Reading is parallel too: each rank reads its own entries
   * (read_field()). No collective HDF5 call is made, so a failing write (a
   * full disk, a quota) is one rank's error that every rank learns, never
   * a collective call that the others wait in. Writing goes to
   * "<file>.tmp", whose index is read back before it is renamed: a run
   * killed while writing still has its previous checkpoint, and a
   * half-written file is never read.
   */
  struct Checkpoint
  {
    /// Small vectors, the same on every rank (per-vesicle values).
    std::map<std::string, std::vector<double>> vectors;
    std::map<std::string, double>              scalars;
    /// The fields: each rank's own part when written; after read(), their
    /// sizes only (read_field() reads a rank's entries).
    std::map<std::string, FieldPart> fields;

    /// Collective; every rank passes its own parts of the fields and the
    /// same vectors and scalars. Throws (on every rank) a message naming
    /// the file if it cannot be written; the previous file is then left
    /// as it was.
    void
    write(const std::string &filename, const MPI_Comm comm) const;
    /// Collective; every rank gets the scalars, the small vectors and the
    /// field sizes. A file written before fields were told apart (format 2
    /// and 3) holds its fields as vectors, which every rank then gets.
    /// Throws InputError naming "Restart from" and what is wrong with the
    /// file (missing, not HDF5, truncated, incomplete).
    static Checkpoint
    read(const std::string &filename, const MPI_Comm comm);
    /// Collective: the entries of field @p name at @p natural_indices (each
    /// rank its own), read from the file read() read. InputError naming
    /// "Restart from" if a rank cannot read them.
    std::vector<double>
    read_field(const std::string                &name,
               const std::vector<std::uint64_t> &natural_indices,
               const MPI_Comm                    comm) const;

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
      return fields.count(name) > 0;
    }

    /// The file read (for messages).
    std::string source;

  private:
    /// Rank 0: the file without the fields' values (allocated, not
    /// written); returns the file offset of each field's values.
    std::map<std::string, std::uint64_t>
    write_layout(const std::string &filename) const;
    /// Every rank: its own entries of every field, at @p offsets.
    void
    write_field_parts(
      const std::string                          &filename,
      const std::map<std::string, std::uint64_t> &offsets) const;
    /// Rank 0: the index, vectors, scalars and field sizes (not the
    /// fields' values).
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
    /// Called after save() for a checkpoint: drop what the checkpoint does
    /// not hold and a restart from it would not have (a Jacobian kept for
    /// the next Newton solve), so that the run goes on exactly as a restart
    /// from this checkpoint would.
    virtual void
    drop_unsaved_state()
    {}
  };
} // namespace vesicle_iga
