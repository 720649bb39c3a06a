#pragma once
// umbra bench: what accuracy costs in time, per scene and method.

#include <string>
#include <vector>

namespace umbra {

int run_bench_command(const std::vector<std::string>& argv);

}  // namespace umbra
