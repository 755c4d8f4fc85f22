// SPDX-License-Identifier: MIT
// Fail fast (issue 17.8): the checks every writing subcommand runs before reading its inputs.
// The extension lists come from the writers' own tables, so a format added there is accepted
// here; writability is tested by creating a probe file, which also catches read-only mounts and
// root on a read-only file system where access(2) would say yes.
#include "dtm/io/output_check.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string_view>
#include <system_error>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> known_extensions(OutputKind kind) {
    switch (kind) {
        case OutputKind::tin: {
            std::vector<std::string> out;
            for (const std::string_view e : tin_extensions()) out.emplace_back(e);
            return out;
        }
        case OutputKind::raster:
            return grid_extensions();
        case OutputKind::contours:
            return contour_extensions();
        case OutputKind::drawing:
            return {"pdf", "svg", "png"};
        default:
            return {};
    }
}

const char* kind_name(OutputKind kind) {
    switch (kind) {
        case OutputKind::tin:
            return "TIN";
        case OutputKind::raster:
            return "raster";
        case OutputKind::drawing:
            return "drawing";
        case OutputKind::contours:
            return "contour";
        default:
            return "";
    }
}

void check_extension(const fs::path& path, OutputKind kind, const std::string& field) {
    const std::vector<std::string> known = known_extensions(kind);
    const std::string extension = lower_extension(path);
    if (known.empty() || std::find(known.begin(), known.end(), extension) != known.end()) return;
    std::string list;
    for (const std::string& e : known) list += (list.empty() ? "." : ", .") + e;
    throw OptionError(field, "`" + field + "` " + path.string() + ": no " + kind_name(kind) +
                                 " writer for the extension '" +
                                 (extension.empty() ? std::string("(none)") : "." + extension) +
                                 "' (known: " + list + ")");
}

/// Creates and removes a hidden probe file in @p folder. @throws OptionError
void probe_folder(const fs::path& folder, const fs::path& path, const std::string& field) {
    const fs::path probe = folder / (".dtm-write-probe-" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        const int error = errno;
        throw OptionError(field, "`" + field + "` " + path.string() +
                                     ": cannot write in the folder " + folder.string() + ": " +
                                     std::strerror(error));
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

}  // namespace

void check_output(const fs::path& path, OutputKind kind, const std::string& field) {
    std::error_code ec;
    if (path.empty()) throw OptionError(field, "`" + field + "` is empty");
    if (kind == OutputKind::folder) {
        fs::path target = path.filename().empty() ? path.parent_path() : path;
        if (fs::exists(target, ec) && !fs::is_directory(target, ec)) {
            throw OptionError(field,
                              "`" + field + "` " + target.string() + " is a file, not a folder");
        }
        // The staging folder is a sibling of the target: its parent must be writable.
        fs::path folder = fs::absolute(target, ec).parent_path();
        while (!folder.empty() && !fs::exists(folder, ec) && folder != folder.parent_path()) {
            folder = folder.parent_path();
        }
        if (!fs::is_directory(folder, ec)) {
            throw OptionError(field, "`" + field + "` " + path.string() + ": " + folder.string() +
                                         " is not a folder");
        }
        probe_folder(folder, path, field);
        return;
    }
    check_extension(path, kind, field);
    if (fs::is_directory(path, ec)) {
        throw OptionError(field, "`" + field + "` " + path.string() + " is a folder, not a file");
    }
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, ec)) {
        throw OptionError(field, "`" + field + "` " + path.string() + ": the folder " +
                                     folder.string() + " does not exist");
    }
    probe_folder(folder, path, field);
}

}  // namespace dtm::io
