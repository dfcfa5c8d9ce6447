#pragma once
// Whole-run outputs: a command writes every output into a temporary sibling of its output folder
// and renames it into place at the end, so a failed or killed run leaves either the complete new
// outputs or the complete old ones, never a mix. Use it in every command that writes a
// folder:
//
//   OutputFolder out(args.out);              // ".NAME.partial-PID" beside NAME, empty
//   writeSweepOutputs(out.getPath(), ...);  // write everything there
//   out.commit();                           // NAME now holds exactly these outputs
//
// commit() swaps the folders atomically (Linux renameat2 RENAME_EXCHANGE) when NAME exists, else
// renames; where the exchange is not supported the old folder is first renamed to
// ".NAME.backup-PID", kept until the new one is in place. Without commit() (an exception) the
// destructor removes the temporary folder and NAME is untouched. A killed run leaves its temporary
// folder behind; the next OutputFolder for NAME removes it (its process is gone) and restores a
// backup left by a kill between the two renames of the fallback.
//
// Nothing a user owns is replaced: every output folder holds the marker file kOutputMarker, and an
// existing folder is replaced only if it holds that marker (or is empty). A folder that holds an
// input of the run (any file read through io/input_file.h) is never replaced. Both are InputErrors
// (key "--out") naming the folder, checked when the OutputFolder is made and again at commit().
#include <filesystem>
#include <string>

namespace motostab::io {

/// The marker file in every output folder: motostab wrote the folder and may replace it.
constexpr const char* kOutputMarker = ".motostab-output";

/// Why `name` (a scenario's name, a file stem) cannot name a folder of its own in the working folder, or
/// "" if it can: it is empty, "." or "..", longer than 200 bytes, or holds a path separator '/' or a
/// control character.
std::string describeBadFolderName(const std::string& name);

/// Throws InputError (key "--out") unless the single output file `file` may be written: it is absent, or
/// a regular file whose first line starts with `header` (motostab wrote it), and it is not an input of
/// this run (io/input_file.h).
void checkFileReplaceable(const std::filesystem::path& file, const std::string& header);

/// Throws InputError (key "--out") unless `target` may be replaced by a run's outputs: it is absent, or
/// an empty folder, or a folder holding kOutputMarker; and it holds no input file of this run
/// (io/input_file.h, getInputFiles).
void checkReplaceable(const std::filesystem::path& target);

class OutputFolder {
 public:
  /// Prepares a temporary folder beside `target`, holding only kOutputMarker. Throws InputError (key
  /// "--out") if `target` may not be replaced (checkReplaceable), std::runtime_error if the folder
  /// cannot be created.
  explicit OutputFolder(std::filesystem::path target);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// Removes the temporary folder unless committed.
  ~OutputFolder();

  /// The folder to write into until commit() (the temporary one).
  const std::filesystem::path& getPath() const { return temporary_; }
  /// The final folder, as given.
  const std::filesystem::path& getTarget() const { return target_; }
  /// Puts the outputs in place of `target` (replacing any previous outputs as a whole). Throws
  /// InputError if `target` may no longer be replaced (checkReplaceable), std::runtime_error if the
  /// rename fails; `target` then still holds the old outputs.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

}  // namespace motostab::io
