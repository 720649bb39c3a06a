#include "tools/check_report_page.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "image/partial_file.hpp"

namespace umbra {
namespace {

// The page: its style, its table's columns and its script. The rows are
// made by the script from the reports (a page of 10,000 meshes is 10,000
// rows of plain cells and lazily loaded pictures, sorted by moving rows).
const char* const kPageHead = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>umbra check</title>
<style>
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.3em; margin: 0 0 0.3em; }
#summary { margin: 0 0 1em; color: #444; }
#controls { margin: 0 0 1em; display: flex; gap: 1em; align-items: center; }
table { border-collapse: collapse; }
th { position: sticky; top: 0; background: #eee; cursor: pointer; text-align: left; padding: 4px 8px; user-select: none; }
th[aria-sort=ascending]::after { content: " \25B2"; }
th[aria-sort=descending]::after { content: " \25BC"; }
td { border-top: 1px solid #ddd; padding: 4px 8px; vertical-align: top; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
td.picture img { width: 128px; height: 128px; object-fit: contain; background: #ccc; display: block; }
td.mesh { min-width: 12em; max-width: 28em; overflow-wrap: anywhere; }
td.closed, td.not-closed, td.unreadable { min-width: 11em; }
td.why { min-width: 16em; }
.closed { color: #1a7f37; } .not-closed { color: #b35900; } .unreadable { color: #c00; }
</style>
</head>
<body>
<h1>umbra check</h1>
<p id="summary"></p>
<div id="controls">
<label>verdict <select id="verdict">
<option value="all">all</option>
<option value="closed">closed 2-manifolds</option>
<option value="not-closed">not closed 2-manifolds</option>
<option value="solid">solids</option>
<option value="not-solid">not solids</option>
<option value="unreadable">unreadable</option>
</select></label>
<label>mesh <input id="name" type="search" placeholder="part of its path"></label>
<span id="shown"></span>
</div>
<table>
<thead><tr id="columns"></tr></thead>
<tbody id="rows"></tbody>
</table>
)";

const char* const kPageScript = R"(<script>
"use strict";
const reports = JSON.parse(document.getElementById("reports").textContent);
const pictures = JSON.parse(document.getElementById("pictures").textContent);
// Each column: its heading, its value in a report, and whether it is a number.
const columns = [
  ["picture", null, false],
  ["mesh", r => r.path, false],
  ["verdict", r => r.error ? "unreadable: " + r.error : r.verdict.split(": ")[0].split(" (")[0], false],  // the counts have columns
  ["triangles", r => r.triangles, true],
  ["components", r => r.components, true],
  ["border edges", r => r.border_edges, true],
  ["holes", r => r.border_loops, true],
  ["non-manifold edges", r => r.non_manifold_edges, true],
  ["non-manifold vertices", r => r.non_manifold_vertices, true],
  ["self-intersecting pairs", r => r.self_intersections && r.self_intersections.checked ? r.self_intersections.face_pairs : null, true],
  ["faces to flip", r => r.faces_to_flip, true],
  ["volume", r => r.volume, true],
  ["why not a solid", r => r.solid_problems ? r.solid_problems.join(", ") : null, false],
];
const number = new Intl.NumberFormat("en", {maximumSignificantDigits: 6});  // one, not one a cell: making one is slow
const kind = r => r.error ? "unreadable" : r.closed_manifold ? "closed" : "not-closed";
const keys = columns.map(c => c[0].replace(/ /g, "-"));

const head = document.getElementById("columns");
columns.forEach((c, k) => {
  const th = document.createElement("th");
  th.textContent = c[0];
  th.dataset.key = keys[k];
  if (c[1]) th.addEventListener("click", () => {
    const state = readState();
    const order = state.sort === keys[k] && state.order === "ascending" ? "descending" : "ascending";
    writeState({...state, sort: keys[k], order});
  });
  head.appendChild(th);
});

// Paths are shown from the folder they all share; the whole path is the cell's title.
const shared = (() => {
  const paths = reports.map(r => r.path);
  if (paths.length < 2) return paths.length ? paths[0].slice(0, paths[0].lastIndexOf("/") + 1) : "";
  let prefix = paths[0];
  for (const p of paths) while (!p.startsWith(prefix)) prefix = prefix.slice(0, -1);
  return prefix.slice(0, prefix.lastIndexOf("/") + 1);
})();

const body = document.getElementById("rows");
const rows = reports.map((r, i) => {
  const tr = document.createElement("tr");
  tr.dataset.path = r.path;
  tr.dataset.kind = kind(r);
  tr.dataset.solid = r.error ? "unreadable" : r.solid ? "solid" : "not-solid";
  columns.forEach(c => {
    const td = document.createElement("td");
    if (!c[1]) {
      td.className = "picture";
      if (pictures[i]) {
        const a = document.createElement("a"), img = document.createElement("img");
        a.href = pictures[i];
        img.src = pictures[i];
        img.loading = "lazy";
        img.alt = "the defects of " + r.path;
        a.appendChild(img);
        td.appendChild(a);
      }
    } else {
      const v = c[1](r);
      td.textContent = v === null || v === undefined ? "" : c[2] ? number.format(v) : v;
      if (c[2]) td.className = "number";
      if (c[0] === "verdict") td.className = kind(r);
      if (c[0] === "mesh") td.className = "mesh", td.title = v, td.textContent = v.slice(shared.length);
      if (c[0] === "why not a solid") td.className = "why";
    }
    tr.appendChild(td);
  });
  body.appendChild(tr);
  return {tr, report: r};
});

const counts = {closed: 0, "not-closed": 0, unreadable: 0};
let solids = 0;
rows.forEach(x => { counts[x.tr.dataset.kind]++; solids += x.tr.dataset.solid === "solid"; });
document.getElementById("summary").textContent =
  `${rows.length} meshes${shared ? " in " + shared : ""}: ${counts.closed} closed 2-manifolds, ${counts["not-closed"]} not, ` +
  `${counts.unreadable} unreadable; ${solids} solids`;

function readState() {
  const p = new URLSearchParams(location.hash.slice(1));
  return {sort: p.get("sort") || "", order: p.get("order") || "ascending", verdict: p.get("verdict") || "all", name: p.get("name") || ""};
}
function writeState(state) {
  const p = new URLSearchParams();
  for (const [k, v] of Object.entries(state)) if (v && !(k === "verdict" && v === "all")) p.set(k, v);
  location.hash = p.toString();
}
function show() {
  const state = readState();
  document.getElementById("verdict").value = state.verdict;
  document.getElementById("name").value = state.name;
  const k = keys.indexOf(state.sort);
  if (k > 0) {
    const [, value, numeric] = columns[k];
    const sign = state.order === "descending" ? -1 : 1;
    const order = rows.map((x, i) => ({x, i, v: value(x.report)}));
    order.sort((a, b) => {
      const missingA = a.v === null || a.v === undefined, missingB = b.v === null || b.v === undefined;
      if (missingA || missingB) return missingA - missingB || a.i - b.i;  // no value: last, whichever way
      const d = numeric ? a.v - b.v : String(a.v).localeCompare(String(b.v));
      return sign * d || a.i - b.i;
    });
    const moved = document.createDocumentFragment();
    order.forEach(o => moved.appendChild(o.x.tr));
    body.appendChild(moved);
  }
  head.querySelectorAll("th").forEach(th => th.removeAttribute("aria-sort"));
  if (k > 0) head.children[k].setAttribute("aria-sort", state.order);
  let shown = 0;
  const name = state.name.toLowerCase();
  rows.forEach(x => {
    const v = state.verdict;
    const kept = (v === "all" || x.tr.dataset.kind === v || x.tr.dataset.solid === v) &&
                 (!name || x.report.path.toLowerCase().includes(name));
    x.tr.hidden = !kept;
    shown += kept;
  });
  document.getElementById("shown").textContent = `${shown} shown`;
}
document.getElementById("verdict").addEventListener("change", e => writeState({...readState(), verdict: e.target.value}));
document.getElementById("name").addEventListener("input", e => writeState({...readState(), name: e.target.value}));
window.addEventListener("hashchange", show);
show();
// How long the rows took to make, sort and filter (bench/check_report_benchmark.sh reads it).
document.body.dataset.readyMs = Math.round(performance.now());
</script>
</body>
</html>
)";

// JSON text made safe inside a <script> element: '<' appears only inside
// its strings, where \u003c says the same.
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    if (c == '<') out += "\\u003c";
    else out += c;
  }
  return out;
}

// A relative path as a URL's path (RFC 3986): each byte but the unreserved
// ones and the '/' between segments percent-encoded, so that a name is
// never read as a scheme ("javascript:..."), a query ('?'), a fragment
// ('#') or an escape ('%'), and a byte that is not UTF-8 still leads to
// its file.
std::string url_path(const std::string& path) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string url;
  for (const char c : path) {
    const unsigned char b = static_cast<unsigned char>(c);
    const bool unreserved = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '.' ||
                            c == '_' || c == '~';
    if (unreserved || c == '/') url += c;
    else url += '%', url += kHex[b >> 4], url += kHex[b & 15];
  }
  return url;
}

// A report's JSON line as the page holds it: without the component list and
// the examples, which its table does not show and which make most of a
// large mesh's line.
std::string page_record(const std::string& line, const std::string& mesh) {
  if (line.empty()) return nlohmann::json{{"path", mesh}, {"error", "no report"}}.dump();
  nlohmann::ordered_json record = nlohmann::ordered_json::parse(line);
  record.erase("component_list");
  record.erase("examples");
  return record.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace

void write_check_report_page(const std::string& path, const std::vector<std::string>& meshes,
                             const std::vector<std::string>& records, const std::vector<std::string>& pictures) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(path).parent_path();
  std::string reports = "[";
  nlohmann::json links = nlohmann::json::array();
  for (size_t i = 0; i < meshes.size(); ++i) {
    reports += (i ? ",\n" : "\n") + page_record(i < records.size() ? records[i] : "", meshes[i]);
    std::error_code ec;
    const bool drawn = i < pictures.size() && !pictures[i].empty() && fs::is_regular_file(pictures[i], ec);
    links.push_back(drawn ? nlohmann::json(url_path(fs::absolute(pictures[i]).lexically_relative(folder).generic_string()))
                         : nlohmann::json());
  }
  reports += "\n]";
  PartialFile partial(path, "the report");
  std::ofstream out(partial.temporary_path(), std::ios::binary);
  out << kPageHead << "<script type=\"application/json\" id=\"reports\">" << script_safe(reports) << "</script>\n"
      << "<script type=\"application/json\" id=\"pictures\">"
      << script_safe(links.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)) << "</script>\n"
      << kPageScript;
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the report");
  partial.commit();
}

}  // namespace umbra
