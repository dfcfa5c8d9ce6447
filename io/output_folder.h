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
// A sibling's name that would exceed the file systems' 255 bytes (a long NAME) keeps the first 160 bytes
// of NAME and a hash of the whole ("NAME-PREFIX~HASH").
//
// Nothing a user owns is replaced: every output folder holds the marker file kOutputMarker, listing
// every entry motostab wrote there (paths relative to the folder, one a line, after the line
// "entries written:"). An existing folder is replaced only if it is empty, or holds that marker and
// nothing the marker does not list (a file or folder the user added is named in the refusal). A marker
// without a list (written by motostab before markers had one) is trusted as before: its folder is
// replaced whole. A folder that holds an input of the run (any file read through io/input_file.h) is
// never replaced. All are InputErrors (key "--out") naming the folder, checked when the OutputFolder
// is made and again at commit(); so are the system's refusals to create or rename the folders (no
// permission, a name too long), with the system's reason.
#include <filesystem>
#include <string>

namespace motostab::io {

/// The marker file in every output folder: motostab wrote the folder and may replace it.
constexpr const char* kOutputMarker = ".motostab-output";

/// Why `name` (a scenario's name, a file stem) cannot name a folder of its own in the working folder, or
/// "" if it can: it is empty, "." or "..", longer than 200 bytes, holds a path separator '/', a control
/// character (C0, DEL, C1 such as U+0085), a bidirectional-text control (U+061C, U+200E-F, U+202A-E,
/// U+2066-9) or a line separator (U+2028-9), or is not valid UTF-8.
std::string describeBadFolderName(const std::string& name);

/// Throws InputError (key "--out") unless the single output file `file` may be written: it is absent, or
/// a regular file whose first line starts with `header` (motostab wrote it), and it is not an input of
/// this run (io/input_file.h).
void checkFileReplaceable(const std::filesystem::path& file, const std::string& header);

/// Throws InputError (key "--out") unless `target` may be replaced by a run's outputs: it is absent, or
/// an empty folder, or a folder holding kOutputMarker and (when the marker lists them) only the entries
/// it lists; and it holds no input file of this run (io/input_file.h, getInputFiles).
void checkReplaceable(const std::filesystem::path& target);

class OutputFolder {
 public:
  /// Prepares a temporary folder beside `target`, holding only kOutputMarker. Throws InputError (key
  /// "--out") if `target` may not be replaced (checkReplaceable), ends in "." or "..", has a name
  /// longer than 255 bytes, or if the system refuses to create the folder (its reason named).
  explicit OutputFolder(std::filesystem::path target);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  /// Removes the temporary folder unless committed.
  ~OutputFolder();

  /// The folder to write into until commit() (the temporary one).
  const std::filesystem::path& getPath() const { return temporary_; }
  /// The final folder, as given.
  const std::filesystem::path& getTarget() const { return target_; }
  /// Lists the outputs in the marker and puts them in place of `target` (replacing any previous outputs
  /// as a whole). Throws InputError if `target` may no longer be replaced (checkReplaceable) or the
  /// system refuses the rename; `target` then still holds the old outputs.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

}  // namespace motostab::io
