// SVG log-log plots.
#include "report_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace lancer::app {
namespace {

bool plottable(const PlotPoint& point) {
    return std::isfinite(point.x) && std::isfinite(point.y) && point.x > 0.0 && point.y > 0.0;
}

// "0.01", "1", "1000": a decade's label without exponent noise.
std::string decade_label(int exponent) {
    char text[32];
    if (exponent >= 0 && exponent <= 5)
        std::snprintf(text, sizeof text, "%.0f", std::pow(10.0, exponent));
    else if (exponent < 0 && exponent >= -4)
        std::snprintf(text, sizeof text, "%.*f", -exponent, std::pow(10.0, exponent));
    else
        std::snprintf(text, sizeof text, "1e%d", exponent);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

// A log axis spanning whole decades around [low, high].
struct LogAxis {
    int first_decade = 0;
    int last_decade = 1;
    double pixel_start = 0.0;  // where first_decade is drawn
    double pixel_end = 1.0;    // where last_decade is drawn

    LogAxis(double low, double high, double start, double end) : pixel_start(start), pixel_end(end) {
        first_decade = int(std::floor(std::log10(low) + 1e-9));
        last_decade = int(std::ceil(std::log10(high) - 1e-9));
        if (last_decade <= first_decade) last_decade = first_decade + 1;
    }
    double to_pixel(double value) const {
        const double t = (std::log10(value) - first_decade) / double(last_decade - first_decade);
        return pixel_start + t * (pixel_end - pixel_start);
    }
};

}  // namespace

std::string escape_xml(const std::string& text) {
    std::string escaped;
    escaped.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

std::string render_svg(const LogLogPlot& plot, int width, int height) {
    // Margins leave room for tick labels (left, bottom), the title (top) and
    // the legend (right).
    const double left = 70, right = width - 170, top = 40, bottom = height - 55;

    double x_low = std::numeric_limits<double>::max(), x_high = 0.0;
    double y_low = std::numeric_limits<double>::max(), y_high = 0.0;
    for (const PlotSeries& series : plot.series)
        for (const PlotPoint& point : series.points) {
            if (!plottable(point)) continue;
            x_low = std::min(x_low, point.x), x_high = std::max(x_high, point.x);
            y_low = std::min(y_low, point.y), y_high = std::max(y_high, point.y);
        }
    if (x_high == 0.0) x_low = 0.1, x_high = 1.0, y_low = 0.1, y_high = 1.0;  // nothing to plot
    for (const PlotLevel& level : plot.levels)
        if (std::isfinite(level.y) && level.y > 0.0)
            y_low = std::min(y_low, level.y), y_high = std::max(y_high, level.y);
    const LogAxis x_axis(x_low, x_high, left, right);
    const LogAxis y_axis(y_low, y_high, bottom, top);

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<text x=\"" << number((left + right) / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
        << escape_xml(plot.title) << "</text>\n";

    // Grid and ticks: a labelled line at each decade, faint minor ticks at 2..9.
    auto vertical_line = [&](double x, const char* stroke) {
        svg << "<line x1=\"" << number(x) << "\" y1=\"" << number(top) << "\" x2=\"" << number(x) << "\" y2=\""
            << number(bottom) << "\" stroke=\"" << stroke << "\"/>\n";
    };
    auto horizontal_line = [&](double y, const char* stroke) {
        svg << "<line x1=\"" << number(left) << "\" y1=\"" << number(y) << "\" x2=\"" << number(right) << "\" y2=\""
            << number(y) << "\" stroke=\"" << stroke << "\"/>\n";
    };
    for (int d = x_axis.first_decade; d <= x_axis.last_decade; ++d) {
        const double x = x_axis.to_pixel(std::pow(10.0, d));
        vertical_line(x, "#bbb");
        svg << "<text x=\"" << number(x) << "\" y=\"" << number(bottom + 18) << "\" text-anchor=\"middle\">"
            << decade_label(d) << "</text>\n";
        for (int m = 2; m <= 9 && d < x_axis.last_decade; ++m)
            vertical_line(x_axis.to_pixel(m * std::pow(10.0, d)), "#eee");
    }
    for (int d = y_axis.first_decade; d <= y_axis.last_decade; ++d) {
        const double y = y_axis.to_pixel(std::pow(10.0, d));
        horizontal_line(y, "#bbb");
        svg << "<text x=\"" << number(left - 6) << "\" y=\"" << number(y + 4) << "\" text-anchor=\"end\">"
            << decade_label(d) << "</text>\n";
        for (int m = 2; m <= 9 && d < y_axis.last_decade; ++m)
            horizontal_line(y_axis.to_pixel(m * std::pow(10.0, d)), "#eee");
    }
    svg << "<rect x=\"" << number(left) << "\" y=\"" << number(top) << "\" width=\"" << number(right - left)
        << "\" height=\"" << number(bottom - top) << "\" fill=\"none\" stroke=\"black\"/>\n";
    svg << "<text x=\"" << number((left + right) / 2) << "\" y=\"" << number(height - 12)
        << "\" text-anchor=\"middle\">" << escape_xml(plot.x_label) << "</text>\n";
    svg << "<text transform=\"translate(16," << number((top + bottom) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
        << escape_xml(plot.y_label) << "</text>\n";

    // Levels, under the curves.
    for (const PlotLevel& level : plot.levels) {
        if (!(std::isfinite(level.y) && level.y > 0.0)) continue;
        const double y = y_axis.to_pixel(level.y);
        svg << "<line x1=\"" << number(left) << "\" y1=\"" << number(y) << "\" x2=\"" << number(right) << "\" y2=\""
            << number(y) << "\" stroke=\"#555\" stroke-dasharray=\"6,4\"/>\n";
        svg << "<text x=\"" << number(left + 6) << "\" y=\"" << number(y - 5) << "\" fill=\"#555\">"
            << escape_xml(level.label) << "</text>\n";
    }

    // Curves, with a marker per point whose tooltip names the setting.
    for (const PlotSeries& series : plot.series) {
        std::ostringstream path;
        for (const PlotPoint& point : series.points) {
            if (!plottable(point)) continue;
            path << (path.tellp() == 0 ? "M" : " L") << number(x_axis.to_pixel(point.x)) << ','
                 << number(y_axis.to_pixel(point.y));
        }
        if (path.tellp() == 0) continue;
        svg << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << series.colour
            << "\" stroke-width=\"2\"/>\n";
        for (const PlotPoint& point : series.points) {
            if (!plottable(point)) continue;
            svg << "<circle cx=\"" << number(x_axis.to_pixel(point.x)) << "\" cy=\"" << number(y_axis.to_pixel(point.y))
                << "\" r=\"3.5\" fill=\"" << series.colour << "\"><title>"
                << escape_xml(series.name + " " + point.label) << "</title></circle>\n";
        }
    }

    // Legend, right of the plot.
    double legend_y = top + 10;
    for (const PlotSeries& series : plot.series) {
        svg << "<line x1=\"" << number(right + 15) << "\" y1=\"" << number(legend_y) << "\" x2=\"" << number(right + 40)
            << "\" y2=\"" << number(legend_y) << "\" stroke=\"" << series.colour << "\" stroke-width=\"2\"/>\n";
        svg << "<circle cx=\"" << number(right + 27.5) << "\" cy=\"" << number(legend_y) << "\" r=\"3.5\" fill=\""
            << series.colour << "\"/>\n";
        svg << "<text x=\"" << number(right + 48) << "\" y=\"" << number(legend_y + 4) << "\">"
            << escape_xml(series.name) << "</text>\n";
        legend_y += 20;
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace lancer::app
