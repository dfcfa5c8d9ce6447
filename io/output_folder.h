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
#include <filesystem>

namespace motostab::io {

class OutputFolder {
 public:
  /// Prepares an empty temporary folder beside `target`. Throws InputError (key "--out") if
  /// `target` exists and is not a folder, std::runtime_error if the folder cannot be created.
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
  /// std::runtime_error if the rename fails; `target` then still holds the old outputs.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

}  // namespace motostab::io
