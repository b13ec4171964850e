#include "app/output_sink.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>

#include "curdle/error.h"
#include "io/atomic_file.h"
#include "io/bounded_file.h"

namespace fs = std::filesystem;

namespace curdle::app {

void OutputSink::write_via_file(const std::string& name,
                                const std::function<void(const fs::path&)>& fill) {
  const fs::path folder = temporary_folder();
  std::string pattern = (folder / "curdle-XXXXXX").string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0)
    throw InputError("cannot make a temporary file for " + name + " in " + folder.string() + ": " +
                     std::strerror(errno) + "; set TMPDIR to a folder this program may write to");
  ::close(fd);
  struct Remove {
    std::string path;
    ~Remove() { ::unlink(path.c_str()); }
  } remove{pattern};
  fill(pattern);
  const std::string bytes = read_own_file(pattern);
  write(name, [&](std::ostream& out) { out << bytes; });
}

namespace {

// Every path staged by any sink, for remove_staged_files_for_exit.
std::mutex staged_mutex;
std::set<fs::path>& staged_paths() {
  static std::set<fs::path> paths;
  return paths;
}
void forget(const fs::path& p) {
  std::lock_guard<std::mutex> lock(staged_mutex);
  staged_paths().erase(p);
}

}  // namespace

void remove_staged_files_for_exit() {
  staged_mutex.lock();  // never released: no sink stages anything after this
  std::error_code ec;
  for (const fs::path& p : staged_paths()) fs::remove_all(p, ec);
}

namespace {

// Each writer in the process stages apart: two threads writing one directory never share.
std::atomic<uint64_t> writers{0};

// What names the directory now: its device and inode, or nothing when there is none.
std::optional<std::pair<dev_t, ino_t>> identity(const fs::path& dir) {
  struct stat info {};
  if (::stat(dir.c_str(), &info) != 0) return std::nullopt;
  return std::make_pair(info.st_dev, info.st_ino);
}

// Staging directories of runs that were killed (SIGKILL leaves no time to remove them): named
// `prefix`, the process's ID and the writer's number in it, and no process of that ID runs.
void remove_abandoned_staging(const fs::path& parent, const std::string& prefix) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !entry.is_directory(ec)) continue;
    const std::string rest = name.substr(prefix.size());
    const std::string id = rest.substr(0, rest.find('-'));
    pid_t pid = 0;
    const auto [end, bad] = std::from_chars(id.data(), id.data() + id.size(), pid);
    if (bad != std::errc() || end != id.data() + id.size() || pid <= 0) continue;
    if (::kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

}  // namespace

StagingDirectory::StagingDirectory(fs::path dir,
                                   std::function<bool(const std::string&, bool)> is_output)
    : dir_(std::move(dir)) {
  // The nearest existing ancestor must be a directory we may write into; nothing is made yet,
  // so that a run that fails leaves no new directory behind.
  std::error_code ec;
  fs::path absolute = fs::absolute(dir_).lexically_normal();
  // A link to a directory is written through: the set goes where it points, the link stays.
  if (fs::is_symlink(absolute, ec) && fs::is_directory(absolute, ec))
    absolute = fs::canonical(absolute, ec);
  place_ = absolute;
  fs::path existing = absolute;
  while (!fs::exists(existing, ec) && existing.has_relative_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError("cannot create the output directory " + dir_.string() + ": " +
                     existing.string() + " is a file in the way");
  if (::access(existing.c_str(), W_OK) != 0) {
    const std::string why = std::strerror(errno);
    if (existing == absolute)
      throw InputError("cannot write into the output directory " + dir_.string() +
                       ": it exists but is not writable (" + why +
                       "); give --out a directory you may write to");
    throw InputError("cannot create the output directory " + dir_.string() + ": " +
                     existing.string() + " is not writable (" + why + ")");
  }
  found_ = identity(absolute);
  // Replaced whole when the directory is new, or holds nothing but this program's outputs.
  whole_ = absolute.has_filename() && absolute != fs::current_path(ec);
  // The new set is staged beside the directory: where its parent may not be written, the
  // files are renamed into the directory one by one instead.
  if (whole_ && fs::exists(absolute, ec) && ::access(absolute.parent_path().c_str(), W_OK) != 0)
    whole_ = false;
  if (whole_ && fs::exists(absolute, ec)) {
    for (const auto& entry : fs::directory_iterator(absolute, ec)) {
      const std::string name = entry.path().filename().string();
      const bool folder = entry.is_directory(ec);
      const bool ours = name[0] == '.' ? !folder && name.find(".tmp-") != std::string::npos
                                       : is_output && is_output(name, folder);
      if (!ours) {
        whole_ = false;
        break;
      }
    }
    if (ec) whole_ = false;
  }
  if (whole_) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a chain of + here.
    std::string hidden = ".";
    hidden += absolute.filename().string();
    hidden += ".curdle-";
    remove_abandoned_staging(absolute.parent_path(), hidden);
    hidden += std::to_string(::getpid());
    hidden += '-';
    hidden += std::to_string(++writers);
    staging_ = absolute.parent_path() / hidden;
  }
}

StagingDirectory::~StagingDirectory() {
  if (committed_) return;
  staged_.clear();  // removes the files staged beside their targets
  std::error_code ec;
  if (!staging_.empty()) {
    fs::remove_all(staging_, ec);
    forget(staging_);
  }
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // if empty
}

void StagingDirectory::make_dir(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (!p.has_relative_path() || p == p.parent_path()) break;
  }
  make_output_dir(dir);
  made_.insert(made_.end(), missing.rbegin(), missing.rend());
}

fs::path StagingDirectory::prepare(const std::string& name) {
  // Under the lock that remove_staged_files_for_exit keeps: once it has run, nothing new is
  // staged (this blocks until the process ends).
  std::lock_guard<std::mutex> lock(staged_mutex);
  names_.push_back(name);
  if (whole_) {
    if (!fs::exists(staging_)) {
      make_dir(staging_.parent_path());
      staged_paths().insert(staging_);
      make_output_dir(staging_);
    }
    const fs::path path = staging_ / name;
    if (path.parent_path() != staging_) make_output_dir(path.parent_path());
    return path;
  }
  const fs::path target = place_ / name;
  make_dir(target.parent_path());
  staged_.push_back(std::make_unique<StagedFile>(target));
  staged_paths().insert(staged_.back()->temporary());
  return staged_.back()->temporary();
}

void StagingDirectory::write(const std::string& name,
                             const std::function<void(std::ostream&)>& fill) {
  write_stream(prepare(name), dir_ / name, fill);
}

void StagingDirectory::write_via_file(const std::string& name,
                                      const std::function<void(const fs::path&)>& fill) {
  fill(prepare(name));
}

void StagingDirectory::commit() {
  if (names_.empty()) {  // a run with nothing to write still makes its directory
    make_dir(place_);
    committed_ = true;
    return;
  }
  if (whole_) {
    std::error_code ec;
    // Another run swapped its set in while this one was writing: the first to finish keeps
    // the directory, and this one says so rather than silently replacing it.
    auto replaced = [&] {
      if (identity(place_) != found_)
        throw InputError("cannot write " + dir_.string() +
                         ": another run wrote its outputs there while this one was running; "
                         "they are kept, and this run's were not written (give each run its "
                         "own --out)");
    };
    if (!fs::exists(place_, ec)) {
      std::lock_guard<std::mutex> lock(staged_mutex);  // as below: never a half-removed set
      replaced();
      fs::rename(staging_, place_, ec);
      if (ec) throw InputError("cannot write " + dir_.string() + ": " + ec.message());
    } else {
      // One rename swaps the whole set in: a reader sees the old set or the new, never a mix.
      // It holds the lock an interrupt takes to remove staged files, so that the new set is
      // never half removed while it moves in; once moved, the staging path holds the old set,
      // which an interrupt may remove as well as this run.
      {
        std::lock_guard<std::mutex> lock(staged_mutex);
        replaced();
        if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, place_.c_str(), RENAME_EXCHANGE) != 0)
          throw InputError("cannot replace " + dir_.string() + ": " + std::strerror(errno));
      }
      fs::remove_all(staging_, ec);  // now the old set
    }
    forget(staging_);
    committed_ = true;
    return;
  }
  for (auto& f : staged_) f->check_replaceable();
  for (auto& f : staged_) {
    f->commit();
    forget(f->temporary());
  }
  committed_ = true;
}

std::vector<fs::path> StagingDirectory::files() const {
  // By name: the outputs are written side by side, in no fixed order.
  std::vector<std::string> names = names_;
  std::sort(names.begin(), names.end());
  std::vector<fs::path> files;
  for (const std::string& n : names) files.push_back(dir_ / n);
  return files;
}

void MemorySink::write(const std::string& name, const std::function<void(std::ostream&)>& fill) {
  std::ostringstream out;
  fill(out);
  std::lock_guard<std::mutex> lock(mutex_);
  files_[name] = std::move(out).str();
}

}  // namespace curdle::app
