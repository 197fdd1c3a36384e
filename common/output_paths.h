// Checks on where a command will write, made before any work: a run that would fail to write,
// or write over one of its own inputs, is refused at once with one line, losing nothing.
#pragma once

#include <filesystem>
#include <vector>

namespace hmcr {

// Creates the folder the file goes into and checks that the file can be written there (it is
// not a folder, the folder is writable). Throws InputError "cannot write PATH: why".
void prepare_output_file(const std::filesystem::path& file);
// The same for an output folder (an existing file of that name is an error).
void prepare_output_dir(const std::filesystem::path& dir);

// Throws InputError when an output is one of the inputs or another output (the same file by any
// path, link or hard link).
void refuse_overwriting(const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::filesystem::path>& inputs);
// Throws InputError when the output folder is, holds or lies in the input folder.
void refuse_nested_dirs(const std::filesystem::path& output, const std::filesystem::path& input);

}  // namespace hmcr
