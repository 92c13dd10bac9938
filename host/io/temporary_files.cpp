#include "io/temporary_files.h"
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <mutex>
#include <pthread.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace tf {

namespace {

std::mutex registry_mutex;

std::vector<std::string>& registry()
{
    static std::vector<std::string> paths;
    return paths;
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
    {
        std::lock_guard<std::mutex> lock(registry_mutex); // held until the process ends: no new temporaries
        // The other threads still run while this one removes: a command writing into a staging directory
        // (bench: create_directories of images/SCENE, then its files) can put back what was just removed, and
        // remove_all of a directory that gains an entry meanwhile fails. So remove until nothing is left, a
        // bounded number of rounds a millisecond apart (the writer is between two files after the first).
        for (int round = 0; round < 100; ++round) {
            bool left = false;
            for (const std::string& path : registry()) {
                std::error_code ignored;
                std::filesystem::remove_all(path, ignored);
                left = left || std::filesystem::exists(path, ignored);
            }
            if (!left)
                break;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        // End as the signal would have: its default action, delivered to this thread.
        std::signal(signal_number, SIG_DFL);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, signal_number);
        pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
        raise(signal_number);
        _exit(128 + signal_number);
    }
}

} // namespace

void install_signal_cleanup()
{
    sigset_t set = cleanup_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(remove_temporaries_on_signal, set).detach();
}

void register_temporary(const std::string& path)
{
    std::lock_guard<std::mutex> lock(registry_mutex);
    std::vector<std::string>& paths = registry();
    if (std::find(paths.begin(), paths.end(), path) == paths.end())
        paths.push_back(path);
}

} // namespace tf
