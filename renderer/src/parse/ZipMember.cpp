#include "parse/ZipMember.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <memory>

#include "core/Error.h"

namespace bxdflab {

namespace {

struct ZipCloser {
    void operator()(zip_t* archive) const { zip_discard(archive); }  // read only: nothing to write back
};
struct ZipFileCloser {
    void operator()(zip_file_t* file) const { zip_fclose(file); }
};
using ZipHandle = std::unique_ptr<zip_t, ZipCloser>;

ZipHandle openZip(std::string const& path, std::string* why) {
    int error = 0;
    zip_t* archive = zip_open(path.c_str(), ZIP_RDONLY, &error);
    if (!archive && why) {
        zip_error_t details;
        zip_error_init_with_code(&details, error);
        *why = zip_error_strerror(&details);
        zip_error_fini(&details);
    }
    return ZipHandle(archive);
}

/// Up to a few member names, for a message about a member that is not there.
std::string someMembers(zip_t* archive) {
    zip_int64_t const count = zip_get_num_entries(archive, 0);
    std::string list;
    for (zip_int64_t i = 0; i < count && i < 8; ++i)
        if (char const* name = zip_get_name(archive, static_cast<zip_uint64_t>(i), 0))
            list += std::string(list.empty() ? "" : ", ") + "\"" + name + "\"";
    if (count > 8) list += ", ... (" + std::to_string(count) + " in all)";
    return count == 0 ? "it is empty" : "it holds " + list;
}

/// The open zip file and the member's index in it; on failure a null handle and `problem` says why.
ZipHandle locateMember(ZipMemberName const& name, zip_int64_t& index, std::string& problem) {
    std::string why;
    ZipHandle archive = openZip(name.zipFile, &why);
    index = archive ? zip_name_locate(archive.get(), name.member.c_str(), 0) : -1;
    if (!archive)
        problem = "cannot read \"" + name.zipFile + "\" as a zip file (" + why + ")";
    else if (index < 0)
        problem = "\"" + name.zipFile + "\" has no member \"" + name.member + "\"; " + someMembers(archive.get());
    return index < 0 ? ZipHandle() : std::move(archive);
}

}  // namespace

std::optional<ZipMemberName> splitZipMemberName(std::string const& name) {
    size_t const bang = name.find('!');
    if (bang == std::string::npos || bang < 4 || bang + 1 >= name.size()) return std::nullopt;
    std::string extension = name.substr(bang - 4, 4);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".zip") return std::nullopt;
    return ZipMemberName{name.substr(0, bang), name.substr(bang + 1)};
}

std::string zipMemberProblem(ZipMemberName const& name) {
    zip_int64_t index;
    std::string problem;
    locateMember(name, index, problem);
    return problem;
}

std::string readZipMember(ZipMemberName const& name, size_t maxBytes) {
    std::string const whole = name.zipFile + "!" + name.member;
    zip_int64_t index;
    std::string problem;
    ZipHandle archive = locateMember(name, index, problem);
    if (!archive) throw RenderError(problem);
    zip_stat_t info;
    zip_stat_init(&info);
    if (zip_stat_index(archive.get(), static_cast<zip_uint64_t>(index), 0, &info) != 0 || !(info.valid & ZIP_STAT_SIZE))
        throw RenderError("cannot read \"" + whole + "\" (" + zip_strerror(archive.get()) + ")");
    if (info.size > maxBytes) throw RenderError("\"" + whole + "\" is larger than " + std::to_string(maxBytes >> 20) + " MiB");
    std::unique_ptr<zip_file_t, ZipFileCloser> file(zip_fopen_index(archive.get(), static_cast<zip_uint64_t>(index), 0));
    if (!file) throw RenderError("cannot read \"" + whole + "\" (" + zip_strerror(archive.get()) + ")");
    std::string bytes(static_cast<size_t>(info.size), '\0');
    size_t done = 0;
    while (done < bytes.size()) {
        zip_int64_t const got = zip_fread(file.get(), &bytes[done], bytes.size() - done);
        if (got <= 0) throw RenderError("\"" + whole + "\" ends early or is corrupt (" + zip_file_strerror(file.get()) + ")");
        done += static_cast<size_t>(got);
    }
    return bytes;
}

}  // namespace bxdflab
