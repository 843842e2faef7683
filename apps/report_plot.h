// Log-log line plots written as hand-made SVG: one curve per series, decade
// ticks, axis labels and a legend. Used by `lancer trade` for error versus
// time; knows nothing about rendering.
#pragma once

#include <string>
#include <vector>

namespace lancer::app {

struct PlotPoint {
    double x = 0.0;
    double y = 0.0;
    std::string label;  // shown as the point's tooltip
};

struct PlotSeries {
    std::string name;               // legend entry
    std::string colour;             // any CSS colour
    std::vector<PlotPoint> points;  // drawn in the given order
};

// A horizontal dashed line across the plot, e.g. a noise floor.
struct PlotLevel {
    double y = 0.0;
    std::string label;
};

struct LogLogPlot {
    std::string title;
    std::string x_label;
    std::string y_label;
    std::vector<PlotSeries> series;
    std::vector<PlotLevel> levels;
};

// The plot as a standalone SVG document. Points with a non-positive or
// non-finite coordinate cannot sit on log axes and are left out.
std::string render_svg(const LogLogPlot& plot, int width = 720, int height = 480);

// Escapes &, <, >, " for XML/HTML text and attributes.
std::string escape_xml(const std::string& text);

}  // namespace lancer::app
