#include "io/temporary_files.h"
#include "texture/error.h"
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <mutex>
#include <pthread.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace tf {

namespace {

namespace fs = std::filesystem;

std::mutex registry_mutex;

std::vector<std::string>& registry()
{
    static std::vector<std::string> paths;
    return paths;
}

// Removes what is registered, until nothing is left: another thread may still be writing into a staging
// directory (bench: create_directories of images/SCENE, then its files) and put back what was just removed,
// and remove_all of a directory that gains an entry meanwhile fails. A bounded number of rounds a
// millisecond apart (the writer is between two files after the first). Called with registry_mutex held.
void remove_registered()
{
    for (int round = 0; round < 100; ++round) {
        bool left = false;
        for (const std::string& path : registry()) {
            std::error_code ignored;
            fs::remove_all(path, ignored); // a link inside is removed, never followed
            left = left || fs::exists(fs::symlink_status(path, ignored));
        }
        if (!left)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    registry().clear();
}

void remove_at_exit()
{
    std::lock_guard<std::mutex> lock(registry_mutex);
    remove_registered();
}

sigset_t cleanup_signals()
{
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    return set;
}

[[noreturn]] void remove_temporaries_on_signal(sigset_t set)
{
    int signal_number = 0;
    while (sigwait(&set, &signal_number) != 0) {
    }
    registry_mutex.lock(); // held until the process ends: no new temporaries
    remove_registered();
    // End as the signal would have: its default action, delivered to this thread.
    std::signal(signal_number, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, signal_number);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    raise(signal_number);
    _exit(128 + signal_number);
}

// NAME.tmp-XXXXXX beside target, X from the kernel's random source; NAME shortened so that the whole stays
// within the directory's name limit.
std::string random_name_beside(const std::string& target)
{
    static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    unsigned char random[6];
    if (getrandom(random, sizeof random, 0) != ssize_t(sizeof random))
        throw Error(target + ": no random numbers for a temporary name (" + std::strerror(errno) + ")");
    std::string suffix = ".tmp-";
    for (unsigned char r : random)
        suffix += alphabet[r % (sizeof alphabet - 1)];
    const fs::path p(target);
    const fs::path directory = p.parent_path();
    long name_max = pathconf(directory.empty() ? "." : directory.c_str(), _PC_NAME_MAX);
    if (name_max <= 0)
        name_max = NAME_MAX;
    std::string name = p.filename().string();
    if (name.size() + suffix.size() > size_t(name_max))
        name.resize(size_t(name_max) - std::min(size_t(name_max), suffix.size()));
    return (directory / (name + suffix)).string();
}

std::string directory_of(const std::string& target)
{
    const fs::path parent = fs::path(target).parent_path();
    return parent.empty() ? "." : parent.string();
}

} // namespace

void install_signal_cleanup()
{
    sigset_t set = cleanup_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(remove_temporaries_on_signal, set).detach();
    registry(); // made before the exit handler is registered, so it is destroyed after the handler runs
    std::atexit(remove_at_exit); // main's return after an error, and exit() anywhere
}

TemporaryFile create_temporary_file(const std::string& target)
{
    for (int attempt = 0; attempt < 100; ++attempt) { // a name taken (by anyone) is skipped, never reused
        TemporaryFile file;
        file.path = random_name_beside(target);
        std::lock_guard<std::mutex> lock(registry_mutex); // a signal now removes it or finds it not yet made
        const int fd = open(file.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd < 0) {
            if (errno == EEXIST)
                continue;
            throw Error(target + ": cannot create files in " + directory_of(target) + " (" + std::strerror(errno) +
                        ")");
        }
        struct stat status {};
        fstat(fd, &status);
        close(fd);
        file.device = status.st_dev;
        file.inode = status.st_ino;
        registry().push_back(file.path);
        return file;
    }
    throw Error(target + ": no free temporary name in " + directory_of(target) + " after 100 tries");
}

int open_temporary_file(const TemporaryFile& file, const std::string& target)
{
    const int fd = open(file.path.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat status {};
    if (fd < 0 || fstat(fd, &status) != 0 || status.st_dev != file.device || status.st_ino != file.inode ||
        !S_ISREG(status.st_mode)) {
        const int error = errno;
        if (fd >= 0)
            close(fd);
        throw Error(target + ": its temporary file " + file.path + " was replaced or removed by someone else (" +
                    (fd < 0 ? std::strerror(error) : "another file") + "); nothing written");
    }
    if (ftruncate(fd, 0) != 0) {
        const int error = errno;
        close(fd);
        throw Error(target + ": cannot write the file (" + std::strerror(error) + ")");
    }
    return fd;
}

std::string create_temporary_directory(const std::string& target)
{
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string path = random_name_beside(target);
        std::lock_guard<std::mutex> lock(registry_mutex);
        if (mkdir(path.c_str(), 0700) != 0) { // fails on anything that exists there, a link included
            if (errno == EEXIST)
                continue;
            throw Error(target + ": cannot create a directory in " + directory_of(target) + " (" +
                        std::strerror(errno) + ")");
        }
        registry().push_back(path);
        return path;
    }
    throw Error(target + ": no free temporary name in " + directory_of(target) + " after 100 tries");
}

void release_temporary(const std::string& path)
{
    std::lock_guard<std::mutex> lock(registry_mutex);
    std::vector<std::string>& paths = registry();
    paths.erase(std::remove(paths.begin(), paths.end(), path), paths.end());
}

void remove_temporary(const std::string& path)
{
    std::lock_guard<std::mutex> lock(registry_mutex);
    std::vector<std::string>& paths = registry();
    if (std::find(paths.begin(), paths.end(), path) == paths.end())
        return; // not ours (or already gone): never removed
    std::error_code ignored;
    fs::remove_all(path, ignored);
    paths.erase(std::remove(paths.begin(), paths.end(), path), paths.end());
}

} // namespace tf
