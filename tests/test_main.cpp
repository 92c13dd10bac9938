// The one main of every test executable: doctest's runner, plus the `ctest` reporter that
// tests/doctest_tests.cmake reads at build time to register each test case as its own ctest test.
#define DOCTEST_CONFIG_IMPLEMENT
#include "support.h"

#include <ostream>
#include <string>

namespace {

// `--list-test-cases --reporters=ctest` prints "tf-test-case<TAB>NAME<TAB>SUITE" a case: the suite's
// words become the ctest test's labels (tests/README.md).
struct CtestListReporter : tf::test::QuietReporter {
    std::ostream& out;
    explicit CtestListReporter(const doctest::ContextOptions& options) : out(*options.cout) {}
    void report_query(const doctest::QueryData& query) override
    {
        for (unsigned i = 0; i < query.num_data; ++i)
            out << "tf-test-case\t" << query.data[i]->m_name << "\t" << query.data[i]->m_test_suite << "\n";
    }
};
DOCTEST_REGISTER_REPORTER("ctest", 1, CtestListReporter);

} // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--tf-list-checks")
            tf::test::set_listing_checks(); // named checks print their ids (support.h); doctest ignores the flag
    doctest::Context context(argc, argv);
    const int status = context.run();
    tf::test::run_end_of_run(); // Vulkan objects the cases kept end here, not in static destructors
    return status;
}
