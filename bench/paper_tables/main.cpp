// opx-paper-tables: reproduces the tables of the paper's section V with
// FCL 0.7 and OctoProx on this machine.
//   opx-paper-tables --table I|II|III|IV [--queries N] [--quick] [--json FILE]
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "options.hpp"
#include "tables.hpp"

namespace paper_tables {
namespace {

void print_usage(std::ostream &out) {
    out << "usage: opx-paper-tables --table I|II|III|IV [--queries N] [--repetitions R] [--quick] [--json FILE]\n"
           "  --table T        the paper's table to reproduce (implemented: I, II, III, IV)\n"
           "  --queries N      T_q is the mean over N identical queries (default 1000; III: 100;\n"
           "                   I: 1000 at 7,784 cells, at most 100 at 25k-300k);\n"
           "                   IV: N PR2 configurations per set (default 100), 3 rounds\n"
           "  --repetitions R  T_{1,1}, T_{1,2} are medians over R builds (default 10; I: 5)\n"
           "  --quick          smoke run: 20 queries (IV: 5 configurations, 1 round), 1 repetition\n"
           "                   (checks stay on)\n"
           "  --json FILE      also write the rows as a JSON array\n";
}

bool parse_positive(const char *text, int &out) {
    char *end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || value > 100000000) return false;
    out = static_cast<int>(value);
    return true;
}

// "2" and "ii" are accepted for "II".
std::string normalized_table(std::string name) {
    for (char &c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (name == "1") return "I";
    if (name == "2") return "II";
    if (name == "3") return "III";
    if (name == "4") return "IV";
    return name;
}

// Distance queries are slower than collision queries: Table III runs fewer.
// Table IV: configurations per set.
int default_query_count(const std::string &table) { return table == "III" || table == "IV" ? 100 : 1000; }
int quick_query_count(const std::string &table) { return table == "IV" ? 5 : 20; }

// Returns false (after a message) on a bad command line.
bool parse_options(int argc, char **argv, BenchOptions &options) {
    bool queries_given = false, repetitions_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--table" && has_value) {
            options.table = normalized_table(argv[++i]);
        } else if (arg == "--queries" && has_value && parse_positive(argv[++i], options.queries)) {
            queries_given = true;
        } else if (arg == "--repetitions" && has_value && parse_positive(argv[++i], options.repetitions)) {
            repetitions_given = true;
        } else if (arg == "--json" && has_value) {
            options.json_path = argv[++i];
        } else {
            std::cerr << "opx-paper-tables: bad argument '" << arg << "'\n";
            return false;
        }
    }
    if (!queries_given) options.queries = options.quick ? quick_query_count(options.table) : default_query_count(options.table);
    if (options.table == "I" && !repetitions_given) options.repetitions = 5;
    if (options.quick && !repetitions_given) options.repetitions = 1;
    return true;
}

int run(const BenchOptions &options) {
    if (options.table != "I" && options.table != "II" && options.table != "III" && options.table != "IV") {
        std::cerr << "opx-paper-tables: table '" << options.table << "' is not implemented (yet)\n";
        return 2;
    }
    const std::string cpu = cpu_name();
    std::cout << "CPU: " << cpu << "\n";
    std::cout << "load average at start: " << load_average() << "\n";
    std::vector<TableRow> rows;
    // Table I writes its own JSON; 77 is Table IV's "skipped" (no data).
    int status = options.table == "I"     ? run_table1(options, cpu)
                 : options.table == "III" ? run_table3(options, cpu, rows)
                 : options.table == "IV"  ? run_table4(options, cpu, rows)
                                          : run_table2(options, cpu, rows);
    if (status == 77) return status;
    if (options.table != "I" && !options.json_path.empty() && !write_json(options.json_path, rows)) {
        std::cerr << "opx-paper-tables: cannot write " << options.json_path << "\n";
        status = status != 0 ? status : 1;
    }
    std::cout << "\nload average at end: " << load_average() << "\n";
    std::cout << "peak RSS: " << three_significant(peak_rss_mib()) << " MiB\n";
    return status;
}

}  // namespace
}  // namespace paper_tables

int main(int argc, char **argv) {
    using namespace paper_tables;
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        print_usage(std::cout);
        return 0;
    }
    BenchOptions options;
    if (!parse_options(argc, argv, options) || options.table.empty()) {
        print_usage(std::cerr);
        return 2;
    }
    try {
        return run(options);
    } catch (const std::exception &error) {
        std::cerr << "opx-paper-tables: " << error.what() << "\n";
        return 1;
    }
}
