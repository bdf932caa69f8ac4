// Learning curves and value images as CSV/data files plus PNGs rendered by gnuplot. Each PNG's
// gnuplot script is kept next to it (<png>.gp) so a plot can be restyled and re-rendered by hand.
#pragma once
#include <string>
#include <vector>

#include "value_image.hpp"

namespace verve::demo {

struct CurveSeries {
    std::string label;
    std::vector<double> values;  // per trial; may be shorter than the longest series
};

// Columns: trial, mean (over the series still running at that trial), then one per series
// (empty where a series has ended).
void writeCurveCsv(const std::string& path, const std::vector<CurveSeries>& series);

// The CSV above as a PNG: each series thin, their mean thick (when more than one series).
// Returns false (after saying why on stderr) when gnuplot is missing or fails.
bool plotCurve(const std::string& csvPath, const std::string& pngPath, const std::string& title,
               const std::string& xLabel, const std::string& yLabel, std::size_t seriesCount, bool logY = false);

// Columns 2, 3, ... of a CSV (x in column 1, a header row) as one labelled line each.
bool plotColumns(const std::string& csvPath, const std::string& pngPath, const std::string& title,
                 const std::string& xLabel, const std::string& yLabel, const std::vector<std::string>& labels);

// Writes the samples as "x y value" rows (or "x value" for one axis) and renders a heat map
// (a line for one axis).
bool plotValueImage(const ValueImage& image, const std::string& dataPath, const std::string& pngPath,
                    const std::string& title);

bool gnuplotAvailable();

}  // namespace verve::demo
