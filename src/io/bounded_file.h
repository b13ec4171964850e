// Files read whole: one a user names, read as hostile input (a regular file, never a device or
// a pipe, of at most a bound, refused if it grows while read), and one curdle wrote itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace curdle {

// A text file a user names: a regular file of at most `max_bytes`. `what` names it in messages
// ("the recipe"), `kind` says what it should be. InputError located at the path otherwise.
std::string read_bounded_text(const std::string& path, const std::string& what,
                              const std::string& kind, uint64_t max_bytes);

// The bytes of a file curdle made (a temporary file a library wrote to); empty if it is gone.
std::string read_own_file(const std::filesystem::path& path);

}  // namespace curdle
