#include "output_path.h"
#include "error.h"
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace tf {

void check_output_path(const std::string& path, const std::vector<std::string>& extensions)
{
    namespace fs = std::filesystem;
    fs::path p(path);
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
        std::string list;
        for (const std::string& e : extensions)
            list += (list.empty() ? "" : " or ") + e;
        throw Error(path + ": unsupported output format '" + ext + "' (use " + list + ")");
    }
    std::error_code ec;
    if (fs::is_directory(p, ec))
        throw Error(path + ": is a directory, not an output file");
    fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (!fs::is_directory(parent, ec))
        throw Error(path + ": the output directory " + parent.string() + " does not exist");
}

std::string temporary_path_for(const std::string& path) { return path + ".tmp-" + std::to_string(getpid()); }

void write_file_atomic(const std::string& path, const std::string& content)
{
    std::string temp = temporary_path_for(path);
    {
        std::ofstream out(temp, std::ios::binary);
        if (out)
            out << content;
        out.close();
        if (!out) {
            std::remove(temp.c_str());
            throw Error(path + ": cannot write the file");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        throw Error(path + ": cannot write the file (" + ec.message() + ")");
    }
}

} // namespace tf
