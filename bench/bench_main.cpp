// snow_bench: Google Benchmark's main plus --smoke, which CI uses to run each
// benchmark once at its smallest size (numbers from a smoke run mean nothing).
#include "bench_scene.hpp"

#include <cstring>
#include <string>
#include <vector>

namespace {

/// The smallest arguments of every benchmark family, as they appear in the
/// names (bench_*.cpp): a new family adds its smallest case here.
constexpr const char* smoke_filter = "--benchmark_filter="
                                     "/flakes:10000(/threads:1)?(/real_time)?$"
                                     "|/side:256/patch:8(/|$)"
                                     "|/side:256/landings:256(/|$)"
                                     "|/side:256/windy:16(/|$)"
                                     "|/side:32(/|$)"
                                     "|/side:256/threads:1(/|$)"
                                     "|/cells:32(/|$)"
                                     "|/resolution:256(/|$)"
                                     "|/mib:64/.*threads:1$"
                                     "|/cells:256/view:0/changed:0(/|$)"
                                     "|/bodies:1$"
                                     "|/samples:257(/|$)"
                                     "|^BM_SpeedOfLight/flakes:100000/threads:1/"
                                     "|^BM_VillageTick/threads:1/"
                                     "|^BM_SceneLoad/scene:0/"
                                     "|^BM_SceneRefuse/";

} // namespace

int main(int argc, char** argv) {
    std::vector<char*> args;
    std::string min_time = "--benchmark_min_time=0";
    std::string filter = smoke_filter;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--smoke") == 0) {
            args.push_back(min_time.data());
            args.push_back(filter.data());
        } else {
            args.push_back(argv[i]);
        }
    }
    int n = static_cast<int>(args.size());
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data())) {
        return 2;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
