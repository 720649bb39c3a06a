#pragma once
// `umbra check PATH... --report REPORT.html`: one static web page of a
// folder's reports, a row per mesh with its defect picture, verdict and
// measures, sortable by any column and filtered by verdict, that opens from
// the disk with no server and no network. The reports go in as their JSON
// lines (check --json's), which the page's script reads; the state of its
// sort and filter is kept in the address's fragment
// (#sort=triangles&order=descending&verdict=open), so a view can be linked.

#include <string>
#include <vector>

namespace umbra {

// Writes the page to `path` (whole or not at all), for `meshes` in order,
// each with its JSON line from `records` ({"path", "error"} for one that
// could not be read) and its defect picture in `pictures` (a path, shown
// where that file exists, linked relative to the page). Throws
// std::runtime_error, naming `path`, when it cannot be written.
void write_check_report_page(const std::string& path, const std::vector<std::string>& meshes,
                             const std::vector<std::string>& records, const std::vector<std::string>& pictures);

}  // namespace umbra
