// equation_links: the generated parts of docs/the-text.md — the last column of its equation
// tables (the lines of engine/ that cite each equation) and the counts of them — so that the
// page cannot go stale.
//
//   equation_links --write <source>         rewrites <source>/docs/the-text.md in place
//   equation_links --check <source> <out>   writes what the page should be to <out>; exit 1,
//                                           naming the difference, when the page differs
//   equation_links --tags <source> <file>…  reads explanations (--explain-format json) and
//                                           exits 1, naming it, when an "equation" tag is not
//                                           a list of the page's equations ("3-23, 3-24")
//
// A citation is "eq." (or "Eq.") followed by a number N-M, a range N-M..N-K, or a list of them:
// "eq. 3-16", "eq. 2-1..2-8", "eq. 3-18, 3-19, 3-14". Every cited number must have a row in
// the page: a table line between the markers `<!-- equations: begin -->` and
// `<!-- equations: end -->` whose first cell is the number. Only a row's last cell and the text
// between `<!-- counts: begin -->` and `<!-- counts: end -->` are written; the rest of the page,
// the statements included, is the page's own. Exit codes: 0 current (or written), 1 out of
// date, 2 an error (named on one line).
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Equation = std::pair<int, int>;  // (chapter, number): eq. 3-16 is (3, 16)

std::string name(const Equation& e) {
  return std::to_string(e.first) + "-" + std::to_string(e.second);
}

Equation parse_equation(const std::string& text) {
  const auto dash = text.find('-');
  return {std::stoi(text.substr(0, dash)), std::stoi(text.substr(dash + 1))};
}

// One line of engine/ that cites an equation.
struct Citation {
  std::string file;   // path below engine/, e.g. "constraints/mlcp.cpp"
  int line = 0;       // 1-based
  std::string range;  // "2-1..2-8" when the equation is cited inside a range, else empty
};

using Citations = std::map<Equation, std::vector<Citation>>;

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Where a folder of engine/ stands in the order of the stages, then the rooms around them.
int stage_rank(const std::string& file) {
  static const std::array<const char*, 9> order = {"kinematics", "motion", "constraints", "contact",
                                                   "scene", "trace", "output", "render", "app"};
  const std::string folder = file.substr(0, file.find('/'));
  const auto at = std::find(order.begin(), order.end(), folder);
  return static_cast<int>(at - order.begin());
}

// Adds the equations one citation names: "3-11", or every number of "2-1..2-8".
void add_item(const std::string& item, const Citation& where, Citations& citations) {
  const auto dots = item.find("..");
  if (dots == std::string::npos) {
    citations[parse_equation(item)].push_back(where);
    return;
  }
  const Equation first = parse_equation(item.substr(0, dots));
  const Equation last = parse_equation(item.substr(dots + 2));
  if (first.first != last.first || first.second >= last.second)
    throw std::runtime_error("engine/" + where.file + ":" + std::to_string(where.line) +
                             ": eq. " + item + " is not a range within one chapter");
  Citation in_range = where;
  in_range.range = item;
  for (int n = first.second; n <= last.second; ++n) citations[{first.first, n}].push_back(in_range);
}

// Every `eq. N-M` citation of engine/**/*.{h,cpp}.
Citations scan_engine(const fs::path& engine) {
  static const std::regex citation(R"([Ee]q\. ((\d-\d+(\.\.\d-\d+)?)(, \d-\d+(\.\.\d-\d+)?)*))");
  static const std::regex item(R"(\d-\d+(\.\.\d-\d+)?)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(engine)) {
    const auto extension = entry.path().extension();
    if (entry.is_regular_file() && (extension == ".h" || extension == ".cpp"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  Citations citations;
  for (const auto& path : files) {
    const std::string file = path.lexically_relative(engine).generic_string();
    const auto lines = read_lines(path);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const Citation where{file, static_cast<int>(i + 1), ""};
      for (std::sregex_iterator m(lines[i].begin(), lines[i].end(), citation), end; m != end; ++m) {
        const std::string list = (*m)[1];
        for (std::sregex_iterator n(list.begin(), list.end(), item); n != end; ++n)
          add_item(n->str(), where, citations);
      }
    }
  }
  return citations;
}

// The last cell of an equation's row: its citing lines, grouped by file in stage order.
std::string links_cell(std::vector<Citation> cited) {
  if (cited.empty()) return "—";
  std::sort(cited.begin(), cited.end(), [](const Citation& a, const Citation& b) {
    const int ra = stage_rank(a.file), rb = stage_rank(b.file);
    if (ra != rb) return ra < rb;
    if (a.file != b.file) return a.file < b.file;
    if (a.line != b.line) return a.line < b.line;
    return a.range < b.range;  // a direct citation ("") before the same line's range
  });
  std::string cell;
  std::string file;
  int line = 0;
  for (const auto& c : cited) {
    if (c.file == file && c.line == line) continue;  // a line that names it twice
    cell += c.file == file ? ", " : (file.empty() ? "`" : "; `") + c.file + "` ";
    const std::string line_number = std::to_string(c.line);
    cell += "[" + line_number + "](../engine/" + c.file + "#L" + line_number + ")";
    if (!c.range.empty()) cell += " (" + c.range + ")";
    file = c.file;
    line = c.line;
  }
  return cell;
}

// The cells of a Markdown table line, split at the '|' that are not escaped as "\|".
std::vector<std::size_t> cell_bars(const std::string& line) {
  std::vector<std::size_t> bars;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) bars.push_back(i);
  return bars;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

// The equation of a row ("| 3-16 | … | … |"), or nothing.
bool row_equation(const std::string& line, Equation& equation) {
  static const std::regex number(R"(\d-\d+)");
  const auto bars = cell_bars(line);
  if (bars.size() < 3 || bars.front() != 0) return false;
  const std::string first = trim(line.substr(1, bars[1] - 1));
  if (!std::regex_match(first, number)) return false;
  equation = parse_equation(first);
  return true;
}

std::string counts_text(const std::set<Equation>& rows, const Citations& citations) {
  int direct = 0, in_range = 0;
  std::set<std::pair<std::string, int>> lines;
  std::string uncited;
  int uncited_count = 0;
  for (const auto& e : rows) {
    const auto found = citations.find(e);
    if (found == citations.end()) {
      uncited += (uncited.empty() ? "" : ", ") + name(e);
      ++uncited_count;
      continue;
    }
    const auto& cited = found->second;
    const bool named =
        std::any_of(cited.begin(), cited.end(), [](const Citation& c) { return c.range.empty(); });
    ++(named ? direct : in_range);
  }
  std::set<std::string> files;
  for (const auto& [e, cited] : citations)
    for (const auto& c : cited) {
      lines.insert({c.file, c.line});
      files.insert(c.file);
    }
  const int cited_count = direct + in_range;
  std::ostringstream out;
  out << "The text numbers **" << rows.size() << "** equations, " << name(*rows.begin()) << " … "
      << name(*rows.rbegin()) << ". `engine/` cites **" << cited_count << "** of them, on "
      << lines.size() << " lines of " << files.size() << " files: " << direct
      << " by their own number, " << in_range
      << " only inside a range such as `eq. 2-1..2-8`. Each of the " << cited_count
      << " links, in the tables below, to every line that cites it (" << cited_count << " of "
      << cited_count << "). Not cited in `engine/` (" << uncited_count << "): " << uncited << ".";
  return out.str();
}

// The page as engine/ says it should be: rows' last cells and the counts regenerated.
std::vector<std::string> generate(const std::vector<std::string>& page,
                                  const Citations& citations) {
  enum class Region { none, equations, counts } region = Region::none;
  std::vector<std::string> out;
  std::set<Equation> rows;
  std::size_t counts_at = 0;
  bool saw_equations = false, saw_counts = false;
  for (std::size_t i = 0; i < page.size(); ++i) {
    const std::string& line = page[i];
    if (line.rfind("<!-- equations: begin", 0) == 0) {
      region = Region::equations;
      saw_equations = true;
    }
    if (line.rfind("<!-- equations: end", 0) == 0) region = Region::none;
    if (line.rfind("<!-- counts: end", 0) == 0) region = Region::none;
    if (region == Region::counts) continue;  // regenerated below
    Equation e;
    if (region == Region::equations && row_equation(line, e)) {
      if (!rows.insert(e).second)
        throw std::runtime_error("docs/the-text.md:" + std::to_string(i + 1) +
                                 ": a second row for eq. " + name(e));
      const auto bars = cell_bars(line);
      const auto found = citations.find(e);
      const auto cited = found == citations.end() ? std::vector<Citation>{} : found->second;
      out.push_back(line.substr(0, bars[bars.size() - 2] + 1) + " " + links_cell(cited) + " |");
      continue;
    }
    out.push_back(line);
    if (line.rfind("<!-- counts: begin", 0) == 0) {
      region = Region::counts;
      saw_counts = true;
      counts_at = out.size();
    }
  }
  if (!saw_equations || !saw_counts)
    throw std::runtime_error("docs/the-text.md: the markers <!-- equations: begin --> and "
                             "<!-- counts: begin --> are both needed");
  for (const auto& [e, cited] : citations)
    if (!rows.count(e))
      throw std::runtime_error("engine/" + cited.front().file + ":" +
                               std::to_string(cited.front().line) + ": cites eq. " + name(e) +
                               ", which docs/the-text.md has no row for");
  out.insert(out.begin() + static_cast<long>(counts_at), counts_text(rows, citations));
  return out;
}

void write_lines(const fs::path& path, const std::vector<std::string>& lines) {
  std::ofstream out(path, std::ios::binary);
  for (const auto& line : lines) out << line << '\n';
  if (!out) throw std::runtime_error(path.string() + ": cannot be written");
}

// Names the first difference and the equations whose links changed; 1 when there is one.
int compare(const std::vector<std::string>& page, const std::vector<std::string>& wanted,
            const fs::path& out) {
  if (page == wanted) return 0;
  std::size_t first = 0;
  while (first < page.size() && first < wanted.size() && page[first] == wanted[first]) ++first;
  std::string stale;
  for (std::size_t i = 0; i < std::min(page.size(), wanted.size()); ++i) {
    Equation e;
    if (page[i] != wanted[i] && row_equation(wanted[i], e)) stale += " " + name(e);
  }
  std::cerr << "docs/the-text.md is not what engine/'s eq. comments say, from its line "
            << first + 1 << ":\n"
            << "  the page:     " << (first < page.size() ? page[first] : "(ends)") << "\n"
            << "  engine/ says: " << (first < wanted.size() ? wanted[first] : "(ends)") << "\n";
  if (!stale.empty()) std::cerr << "Links out of date for eq." << stale << ".\n";
  std::cerr << "The page as it should be: " << out.string() << "\n"
            << "Regenerate it with: cmake --build build --target update_the_text\n";
  return 1;
}

}  // namespace

// The equations the page has a row for, between its equation markers.
std::set<Equation> page_equations(const std::vector<std::string>& page) {
  std::set<Equation> rows;
  bool inside = false;
  for (const auto& line : page) {
    if (line.find("<!-- equations: begin") != std::string::npos) inside = true;
    if (line.find("<!-- equations: end") != std::string::npos) inside = false;
    Equation e;
    if (inside && row_equation(line, e)) rows.insert(e);
  }
  return rows;
}

// Every "equation" tag of the explanation files names equations of the page: a list of
// numbers N-M or ranges N-M..N-K, ", "-separated. Prints each that does not; 1 if any.
int check_tags(const std::set<Equation>& rows, const std::vector<std::string>& files) {
  static const std::regex tag(R"re("equation": "([^"]*)")re");
  static const std::regex list(R"((\d-\d+(\.\.\d-\d+)?)(, \d-\d+(\.\.\d-\d+)?)*)");
  static const std::regex item(R"(\d-\d+(\.\.\d-\d+)?)");
  int bad = 0, tags = 0;
  for (const auto& file : files) {
    const auto lines = read_lines(file);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      for (std::sregex_iterator m(lines[i].begin(), lines[i].end(), tag), end; m != end; ++m) {
        const std::string value = (*m)[1];
        if (value.empty()) continue;
        ++tags;
        const std::string where = file + ":" + std::to_string(i + 1) + ": \"" + value + "\"";
        if (!std::regex_match(value, list)) {
          std::cerr << where << " is not a list of equation numbers\n";
          ++bad;
          continue;
        }
        Citations cited;
        for (std::sregex_iterator n(value.begin(), value.end(), item); n != end; ++n)
          add_item(n->str(), Citation{file, static_cast<int>(i + 1), ""}, cited);
        for (const auto& [equation, lines_citing] : cited) {
          if (rows.count(equation)) continue;
          std::cerr << where << ": eq. " << name(equation) << " is not an equation of the text\n";
          ++bad;
        }
      }
    }
  }
  if (tags == 0) {
    std::cerr << "equation_links: no equation tags in the files given\n";
    return 1;
  }
  return bad == 0 ? 0 : 1;
}

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const bool write = args.size() == 2 && args[0] == "--write";
  const bool check = args.size() == 3 && args[0] == "--check";
  const bool tags = args.size() >= 3 && args[0] == "--tags";
  if (!write && !check && !tags) {
    std::cerr << "usage: equation_links --write <source> | --check <source> <out> | "
                 "--tags <source> <file>...\n";
    return 2;
  }
  try {
    const fs::path source = args[1];
    const fs::path doc = source / "docs" / "the-text.md";
    const auto page = read_lines(doc);
    if (tags) return check_tags(page_equations(page), {args.begin() + 2, args.end()});
    const auto wanted = generate(page, scan_engine(source / "engine"));
    if (write) {
      if (page != wanted) write_lines(doc, wanted);
      return 0;
    }
    write_lines(args[2], wanted);
    return compare(page, wanted, args[2]);
  } catch (const std::exception& e) {
    std::cerr << "equation_links: " << e.what() << "\n";
    return 2;
  }
}
