#include "plots.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace verve::demo {

namespace {

std::ofstream openForWriting(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write " + path);
    return out;
}

// Quoted for gnuplot's single-quoted strings (no escapes inside them except '').
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string shellQuoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// pngcairo when gnuplot has it (nicer), else the libgd png terminal.
const char* kTerminal =
    "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) "
    "{ set terminal pngcairo size 900,560 font 'sans,11' } "
    "else { set terminal png size 900,560 }\n";

bool runGnuplot(const std::string& script, const std::string& scriptPath) {
    openForWriting(scriptPath) << script;
    if (!gnuplotAvailable()) {
        std::fprintf(stderr, "gnuplot not found: kept %s, no PNG (apt-get install gnuplot-nox)\n",
                     scriptPath.c_str());
        return false;
    }
    const std::string command = "gnuplot " + shellQuoted(scriptPath);
    if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "gnuplot failed on %s\n", scriptPath.c_str());
        return false;
    }
    return true;
}

}  // namespace

bool gnuplotAvailable() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

void writeCurveCsv(const std::string& path, const std::vector<CurveSeries>& series) {
    std::ofstream out = openForWriting(path);
    std::size_t longest = 0;
    out << "trial,mean";
    for (const CurveSeries& s : series) {
        out << ',' << s.label;
        longest = std::max(longest, s.values.size());
    }
    out << '\n';
    out.precision(6);
    for (std::size_t t = 0; t < longest; ++t) {
        double sum = 0.0;
        int n = 0;
        for (const CurveSeries& s : series)
            if (t < s.values.size()) sum += s.values[t], ++n;
        out << (t + 1) << ',' << sum / n;
        for (const CurveSeries& s : series) {
            out << ',';
            if (t < s.values.size()) out << s.values[t];
        }
        out << '\n';
    }
}

bool plotCurve(const std::string& csvPath, const std::string& pngPath, const std::string& title,
               const std::string& xLabel, const std::string& yLabel, std::size_t seriesCount, bool logY) {
    std::ostringstream gp;
    gp << kTerminal << "set output " << quoted(pngPath) << "\n"
       << "set datafile separator ','\nset key top left\nset grid\n"
       << "set title " << quoted(title) << "\nset xlabel " << quoted(xLabel) << "\nset ylabel "
       << quoted(yLabel) << "\n";
    if (logY) gp << "set logscale y\n";
    gp << "plot ";
    if (seriesCount > 1) {
        gp << "for [i=3:" << seriesCount + 2 << "] " << quoted(csvPath)
           << " using 1:i with lines lw 1 lc rgb '#b0c4de' notitle, \\\n     " << quoted(csvPath)
           << " using 1:2 with lines lw 2.5 lc rgb '#1f4e9c' title 'mean of " << seriesCount << " runs'\n";
    } else {
        gp << quoted(csvPath) << " using 1:2 with lines lw 2 lc rgb '#1f4e9c' notitle\n";
    }
    return runGnuplot(gp.str(), pngPath + ".gp");
}

bool plotColumns(const std::string& csvPath, const std::string& pngPath, const std::string& title,
                 const std::string& xLabel, const std::string& yLabel, const std::vector<std::string>& labels) {
    static const char* const colours[] = {"#c0392b", "#1f4e9c", "#27ae60", "#8e44ad"};
    std::ostringstream gp;
    gp << kTerminal << "set output " << quoted(pngPath) << "\n"
       << "set datafile separator ','\nset key top left\nset grid\n"
       << "set title " << quoted(title) << "\nset xlabel " << quoted(xLabel) << "\nset ylabel "
       << quoted(yLabel) << "\nplot ";
    for (std::size_t i = 0; i < labels.size(); ++i) {
        gp << (i > 0 ? ", \\\n     " : "") << quoted(csvPath) << " using 1:" << i + 2 << " with linespoints lw 2 lc rgb '"
           << colours[i % 4] << "' title " << quoted(labels[i]);
    }
    gp << "\n";
    return runGnuplot(gp.str(), pngPath + ".gp");
}

bool plotValueImage(const ValueImage& image, const std::string& dataPath, const std::string& pngPath,
                    const std::string& title) {
    std::ofstream data = openForWriting(dataPath);
    const ValueAxisInfo& x = image.axes[0];
    if (image.axes.size() == 1) {
        for (std::size_t i = 0; i < x.coordinates.size(); ++i) data << x.coordinates[i] << ' ' << image.values[i] << '\n';
    } else {
        const ValueAxisInfo& y = image.axes[1];
        for (std::size_t j = 0; j < y.coordinates.size(); ++j) {
            for (std::size_t i = 0; i < x.coordinates.size(); ++i)
                data << x.coordinates[i] << ' ' << y.coordinates[j] << ' '
                     << image.values[j * x.coordinates.size() + i] << '\n';
            data << '\n';
        }
    }
    data.close();

    std::ostringstream gp;
    gp << kTerminal << "set output " << quoted(pngPath) << "\nset title " << quoted(title)
       << "\nset xlabel " << quoted(x.label) << "\n";
    if (image.axes.size() == 1) {
        gp << "set ylabel 'value'\nset grid\nplot " << quoted(dataPath) << " using 1:2 with linespoints notitle\n";
    } else {
        const ValueAxisInfo& y = image.axes[1];
        gp << "set ylabel " << quoted(y.label) << "\nset cblabel 'value'\nset palette rgbformulae 33,13,10\n"
           << "set size ratio -1\nset autoscale fix\n";
        // Grid tasks count rows downward from the top, as the thesis's figures show them.
        if (y.axis.kind == SensorKind::Discrete) gp << "set yrange [*:*] reverse\n";
        gp << "plot " << quoted(dataPath) << " using 1:2:3 with image notitle\n";
    }
    return runGnuplot(gp.str(), pngPath + ".gp");
}

}  // namespace verve::demo
