// Built-in functions: POV-Ray's float, vector and string functions. Domain
// errors (sqrt(-1), log(0), ...) are located errors, never NaN or infinity.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <optional>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The functions, told apart by number once their name is looked up.
enum class Builtin : std::uint8_t {
    Abs,
    Sqrt,
    Sqr,
    Pow,
    Exp,
    Log,
    Ln,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Min,
    Max,
    Floor,
    Ceil,
    Mod,
    Int,
    Div,
    Radians,
    Degrees,
    Vlength,
    Vnormalize,
    Vcross,
    Vdot,
    Vrotate,
    VaxisRotate,
    Seed,
    Rand,
    Select,
    Concat,
    Str,
    Strlen,
    Substr,
    Chr,
    Val,
    Strupr,
    Strlwr,
    Vstr,
    Asc,
    BitwiseAnd,
    BitwiseOr,
    FileExists,
    Dimensions,
    DimensionSize,
    Vturbulence,
    BitwiseXor,
    Strcmp,
    Datetime,
};

struct BuiltinEntry {
    Builtin id;
    int least_arguments;
    int most_arguments;
};

struct Call {
    Evaluator& ev;
    const std::string& name;
    const std::vector<Value>& args;
    const SourceRange& where;

    // The messages are built only when needed: a loop calls these a
    // million times.
    double f(size_t i) {
        if (args[i].kind == Value::Kind::Float) return args[i].v[0];
        return ev.to_float(args[i], where, "a float argument " + std::to_string(i + 1) + " of " + name + "()");
    }
    Value number(double x) {
        if (std::isfinite(x)) return Value::number(x);
        return ev.checked(Value::number(x), where, "the result of " + name + "()");
    }
    sg::Vec3 vec(size_t i) { return ev.to_vec3(args[i], where); }
    std::string s(size_t i) { return ev.to_string(args[i], where); }
    void domain(const std::string& problem) { ev.error(where.begin, name + "(): " + problem); }
};

std::string format_number(double value, int width, int precision) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "%*.*f", std::clamp(width, 0, 60), std::clamp(precision, 0, 30), value);
    return buffer;
}

sg::Vec3 rotate_degrees(const sg::Vec3& p, const sg::Vec3& degrees) {
    sg::Mat4 m(1.0);
    m = glm::rotate(sg::Mat4(1.0), glm::radians(degrees.x), sg::Vec3(1, 0, 0));
    m = glm::rotate(sg::Mat4(1.0), glm::radians(degrees.y), sg::Vec3(0, 1, 0)) * m;
    m = glm::rotate(sg::Mat4(1.0), glm::radians(degrees.z), sg::Vec3(0, 0, 1)) * m;
    return sg::Vec3(m * glm::dvec4(p, 0.0));
}

// POV-Ray's limit on datetime()'s format and text.
constexpr std::size_t kLongestDatetimeText = 200;

// POV's datetime(days, format): `days` since 2000-01-01 00:00 UTC (what
// `now` gives), rounded to the second, as strftime writes it in UTC (an
// empty text when strftime cannot: the text would be too long). None for
// a year outside 1400..9999, which POV-Ray's calendar refuses.
std::optional<std::string> datetime_text(double days, const std::string& format) {
    constexpr double kDaysFrom1970To2000 = 365.0 * 30 + 7;
    constexpr double kSecondsFrom1970To10000 = 253402300800.0, kSecondsFrom1400To1970 = 17987443200.0;
    const double seconds = std::floor((days + kDaysFrom1970To2000) * 86400.0 + 0.5);
    if (!(seconds >= -kSecondsFrom1400To1970 && seconds < kSecondsFrom1970To10000)) return std::nullopt;
    const std::time_t stamp = static_cast<std::time_t>(seconds);
    std::tm broken{};
    if (!gmtime_r(&stamp, &broken)) return std::nullopt;
    char text[kLongestDatetimeText + 1];
    const std::size_t length = std::strftime(text, sizeof text - 1, format.c_str(), &broken);
    return std::string(text, length);
}

}  // namespace

// POV-Ray 3.7's generator, so that a scene placing objects at random puts
// them where POV-Ray does: a 32-bit linear congruential step (multiplier
// 1812433253, increment 12345) whose state over 2^32 - 1 is the value, so
// 1 itself can come out. seed(n) starts a stream at n truncated to an int
// and taken modulo 2^32, and returns the stream's number, from 0.
Value builtin_seed(Evaluator& ev, const std::vector<Value>& args, const SourceRange& where) {
    const double s = ev.to_float(args[0], where, "a float seed");
    const double truncated = std::isfinite(s) ? std::clamp(std::trunc(s), -2147483648.0, 2147483647.0) : 0.0;
    ev.m_random_streams.push_back(std::uint32_t(std::int32_t(truncated)));
    return Value::number(double(ev.m_random_streams.size() - 1));
}

Value builtin_rand(Evaluator& ev, const std::vector<Value>& args, const SourceRange& where) {
    const double id = ev.to_float(args[0], where, "a random stream from seed()");
    if (!(id >= 0.0 && id < double(ev.m_random_streams.size()))) {
        ev.error(where.begin, "rand() needs a stream made by seed(), e.g. #declare S = seed(42); rand(S)");
        return Value::number(0.0);
    }
    std::uint32_t& state = ev.m_random_streams[std::size_t(id)];
    state = state * 1812433253u + 12345u;
    return Value::number(double(state) / 4294967295.0);
}

Value Evaluator::call_builtin(const std::string& name, const std::vector<Value>& args, const SourceRange& where) {
    static const std::unordered_map<std::string, BuiltinEntry> table = {
        {"abs", {Builtin::Abs, 1, 1}},
        {"sqrt", {Builtin::Sqrt, 1, 1}},
        {"sqr", {Builtin::Sqr, 1, 1}},
        {"pow", {Builtin::Pow, 2, 2}},
        {"exp", {Builtin::Exp, 1, 1}},
        {"log", {Builtin::Log, 1, 1}},
        {"ln", {Builtin::Ln, 1, 1}},
        {"sin", {Builtin::Sin, 1, 1}},
        {"cos", {Builtin::Cos, 1, 1}},
        {"tan", {Builtin::Tan, 1, 1}},
        {"asin", {Builtin::Asin, 1, 1}},
        {"acos", {Builtin::Acos, 1, 1}},
        {"atan", {Builtin::Atan, 1, 1}},
        {"atan2", {Builtin::Atan2, 2, 2}},
        {"sinh", {Builtin::Sinh, 1, 1}},
        {"cosh", {Builtin::Cosh, 1, 1}},
        {"tanh", {Builtin::Tanh, 1, 1}},
        {"asinh", {Builtin::Asinh, 1, 1}},
        {"acosh", {Builtin::Acosh, 1, 1}},
        {"atanh", {Builtin::Atanh, 1, 1}},
        {"min", {Builtin::Min, 1, 99}},
        {"max", {Builtin::Max, 1, 99}},
        {"floor", {Builtin::Floor, 1, 1}},
        {"ceil", {Builtin::Ceil, 1, 1}},
        {"mod", {Builtin::Mod, 2, 2}},
        {"int", {Builtin::Int, 1, 1}},
        {"div", {Builtin::Div, 2, 2}},
        {"radians", {Builtin::Radians, 1, 1}},
        {"degrees", {Builtin::Degrees, 1, 1}},
        {"vlength", {Builtin::Vlength, 1, 1}},
        {"vnormalize", {Builtin::Vnormalize, 1, 1}},
        {"vcross", {Builtin::Vcross, 2, 2}},
        {"vdot", {Builtin::Vdot, 2, 2}},
        {"vrotate", {Builtin::Vrotate, 2, 2}},
        {"vaxis_rotate", {Builtin::VaxisRotate, 3, 3}},
        {"seed", {Builtin::Seed, 1, 1}},
        {"rand", {Builtin::Rand, 1, 1}},
        {"select", {Builtin::Select, 3, 4}},
        {"concat", {Builtin::Concat, 1, 99}},
        {"str", {Builtin::Str, 3, 3}},
        {"strlen", {Builtin::Strlen, 1, 1}},
        {"substr", {Builtin::Substr, 3, 3}},
        {"chr", {Builtin::Chr, 1, 1}},
        {"val", {Builtin::Val, 1, 1}},
        {"strupr", {Builtin::Strupr, 1, 1}},
        {"strlwr", {Builtin::Strlwr, 1, 1}},
        {"vstr", {Builtin::Vstr, 5, 5}},
        {"asc", {Builtin::Asc, 1, 1}},
        {"bitwise_and", {Builtin::BitwiseAnd, 2, 99}},
        {"bitwise_or", {Builtin::BitwiseOr, 2, 99}},
        {"file_exists", {Builtin::FileExists, 1, 1}},
        {"dimensions", {Builtin::Dimensions, 1, 1}},
        {"dimension_size", {Builtin::DimensionSize, 2, 2}},
        {"vturbulence", {Builtin::Vturbulence, 4, 4}},
        {"bitwise_xor", {Builtin::BitwiseXor, 2, 99}},
        {"strcmp", {Builtin::Strcmp, 2, 2}},
        {"datetime", {Builtin::Datetime, 1, 2}},
    };
    const auto entry = table.find(name);
    if (entry == table.end()) {
        error(where.begin, "unknown function '" + name + "'");
        return Value::number(0.0);
    }
    int count = static_cast<int>(args.size());
    const BuiltinEntry& expected = entry->second;
    if (count < expected.least_arguments || count > expected.most_arguments) {
        std::string wanted = expected.least_arguments == expected.most_arguments
                                 ? std::to_string(expected.least_arguments)
                                 : std::to_string(expected.least_arguments) + " or more";
        error(where.begin, name + "() takes " + wanted + " argument(s), " + std::to_string(count) + " given");
        return Value::number(0.0);
    }
    Call c{*this, name, args, where};
    auto number = [&c](double x) { return c.number(x); };
    const Builtin id = expected.id;

    if (id == Builtin::Dimensions || id == Builtin::DimensionSize) {
        const Value& a = args[0];
        if (a.kind != Value::Kind::Array || !a.array()) {
            error(where.begin, name + "() needs an array, got " + describe(a));
            return Value::number(0.0);
        }
        if (id == Builtin::Dimensions) return number(double(a.array()->sizes.size()));
        const double d = c.f(1);  // POV counts dimensions from 1
        if (!(d >= 1.0) || d > double(a.array()->sizes.size())) {
            error(where.begin, "dimension_size(): the array has " + std::to_string(a.array()->sizes.size()) +
                                   " dimension(s), asked for " + std::to_string(d));
            return Value::number(0.0);
        }
        return number(double(a.array()->sizes[std::size_t(d) - 1]));
    }

    // Float functions.
    if (id == Builtin::Abs) return number(std::fabs(c.f(0)));
    if (id == Builtin::Sqrt) {
        double x = c.f(0);
        if (x < 0) {
            c.domain("square root of a negative number (" + std::to_string(x) + ")");
            return Value::number(0.0);
        }
        return number(std::sqrt(x));
    }
    if (id == Builtin::Sqr) return number(c.f(0) * c.f(0));
    if (id == Builtin::Pow) {
        double base = c.f(0), exponent = c.f(1);
        if (base == 0.0 && exponent < 0.0) {
            c.domain("zero to a negative power");
            return Value::number(0.0);
        }
        if (base < 0.0 && exponent != std::floor(exponent)) {
            c.domain("negative base to a fractional power");
            return Value::number(0.0);
        }
        return number(std::pow(base, exponent));
    }
    if (id == Builtin::Exp) return number(std::exp(c.f(0)));
    if (id == Builtin::Log || id == Builtin::Ln) {
        double x = c.f(0);
        if (x <= 0) {
            c.domain("logarithm of a non-positive number (" + std::to_string(x) + ")");
            return Value::number(0.0);
        }
        return number(id == Builtin::Log ? std::log10(x) : std::log(x));
    }
    if (id == Builtin::Sin) return number(std::sin(c.f(0)));
    if (id == Builtin::Cos) return number(std::cos(c.f(0)));
    if (id == Builtin::Tan) return number(std::tan(c.f(0)));
    if (id == Builtin::Asin || id == Builtin::Acos) {
        double x = c.f(0);
        if (x < -1.0 || x > 1.0) {
            c.domain("argument " + std::to_string(x) + " outside [-1, 1]");
            return Value::number(0.0);
        }
        return number(id == Builtin::Asin ? std::asin(x) : std::acos(x));
    }
    if (id == Builtin::Atan) return number(std::atan(c.f(0)));
    if (id == Builtin::Atan2) return number(std::atan2(c.f(0), c.f(1)));
    if (id == Builtin::Sinh) return number(std::sinh(c.f(0)));
    if (id == Builtin::Cosh) return number(std::cosh(c.f(0)));
    if (id == Builtin::Tanh) return number(std::tanh(c.f(0)));
    if (id == Builtin::Asinh) return number(std::asinh(c.f(0)));
    if (id == Builtin::Acosh) return number(std::acosh(c.f(0)));
    if (id == Builtin::Atanh) return number(std::atanh(c.f(0)));
    if (id == Builtin::Min || id == Builtin::Max) {
        double r = c.f(0);
        for (size_t i = 1; i < args.size(); ++i) r = id == Builtin::Min ? std::min(r, c.f(i)) : std::max(r, c.f(i));
        return number(r);
    }
    if (id == Builtin::Floor) return number(std::floor(c.f(0)));
    if (id == Builtin::Ceil) return number(std::ceil(c.f(0)));
    if (id == Builtin::Int) return number(std::trunc(c.f(0)));
    if (id == Builtin::Mod || id == Builtin::Div) {
        double a = c.f(0), b = c.f(1);
        if (b == 0.0) {
            c.domain("division by zero");
            return Value::number(0.0);
        }
        return number(id == Builtin::Mod ? std::fmod(a, b) : std::trunc(a / b));
    }
    if (id == Builtin::Radians) return number(c.f(0) * kPi / 180.0);
    if (id == Builtin::Degrees) return number(c.f(0) * 180.0 / kPi);
    if (id == Builtin::Select) {
        double s = c.f(0);
        if (args.size() == 3) return s < 0 ? args[1] : args[2];
        return s < 0 ? args[1] : s == 0 ? args[2] : args[3];
    }
    if (id == Builtin::BitwiseAnd || id == Builtin::BitwiseOr || id == Builtin::BitwiseXor) {
        long r = static_cast<long>(c.f(0));
        for (size_t i = 1; i < args.size(); ++i) {
            const long operand = static_cast<long>(c.f(i));
            r = id == Builtin::BitwiseAnd ? r & operand : id == Builtin::BitwiseOr ? r | operand : r ^ operand;
        }
        return number(static_cast<double>(r));
    }
    if (id == Builtin::Seed) return builtin_seed(*this, args, where);
    if (id == Builtin::Rand) return builtin_rand(*this, args, where);

    // Vector functions.
    if (id == Builtin::Vlength) return number(glm::length(c.vec(0)));
    if (id == Builtin::Vnormalize) {
        sg::Vec3 v = c.vec(0);
        if (glm::length(v) == 0.0) {
            c.domain("cannot normalize a zero vector");
            return Value::vec3(sg::Vec3(0.0));
        }
        return Value::vec3(glm::normalize(v));
    }
    if (id == Builtin::Vcross) return checked(Value::vec3(glm::cross(c.vec(0), c.vec(1))), where, "vcross()");
    if (id == Builtin::Vdot) return number(glm::dot(c.vec(0), c.vec(1)));
    if (id == Builtin::Vrotate) return checked(Value::vec3(rotate_degrees(c.vec(0), c.vec(1))), where, "vrotate()");
    if (id == Builtin::VaxisRotate) {
        sg::Vec3 axis = c.vec(1);
        if (glm::length(axis) == 0.0) {
            c.domain("zero rotation axis");
            return args[0];
        }
        sg::Mat4 m = glm::rotate(sg::Mat4(1.0), glm::radians(c.f(2)), glm::normalize(axis));
        return checked(Value::vec3(sg::Vec3(m * glm::dvec4(c.vec(0), 0.0))), where, "vaxis_rotate()");
    }

    if (id == Builtin::Vturbulence) {
        const double lambda = c.f(0), omega = c.f(1), octaves = c.f(2);
        const sg::Vec3 point = c.vec(3);
        if (!m_options.function_natives) {
            error(where.begin, "vturbulence() needs the renderer's noise (lancer render or lancer check)");
            return Value::vec3(sg::Vec3(0.0));
        }
        // POV's (int) then clamp to 1..10; its conversion of a number past
        // int's range (or NaN) gives INT_MIN on x86, so one octave (measured).
        const bool fits_int = octaves >= 1.0 && octaves < 2147483648.0;
        const int clamped_octaves = !fits_int ? 1 : octaves >= 10.0 ? 10 : static_cast<int>(octaves);
        try {
            return checked(
                Value::vec3(m_options.function_natives->turbulence_vector(point, omega, lambda, clamped_octaves)),
                where, "vturbulence()");
        } catch (const sg::FunctionError& e) {
            error(where.begin, e.what());
            return Value::vec3(sg::Vec3(0.0));
        }
    }

    // String functions.
    if (id == Builtin::Concat) {
        std::size_t length = 0;
        for (size_t i = 0; i < args.size(); ++i) length += c.s(i).size();
        // Strings are the one value a scene can grow without bound (a
        // #while that doubles one, a recursive macro that extends one):
        // every concat counts against one budget for the whole parse.
        m_string_bytes += length;
        if (m_string_bytes > std::size_t(m_options.max_string_bytes)) {
            error(where.begin, "the scene's strings have grown past " +
                                   std::to_string(m_options.max_string_bytes >> 20) +
                                   " MiB in all (ParseOptions::max_string_bytes): a loop or recursive macro that "
                                   "keeps concatenating?");
            abort_parse();
            return Value::string("");
        }
        std::string r;
        r.reserve(length);
        for (size_t i = 0; i < args.size(); ++i) r += c.s(i);
        return Value::string(r);
    }
    if (id == Builtin::Str)
        return Value::string(format_number(c.f(0), saturated_int(c.f(1)), c.f(2) < 0 ? 6 : saturated_int(c.f(2))));
    if (id == Builtin::Vstr) {
        int dims = saturated_int(c.f(0));
        const Value& v = args[1];
        std::string sep = c.s(2), r;
        for (int i = 0; i < dims && i < 5; ++i) {
            if (i) r += sep;
            r += format_number(v.v[std::min(i, v.size - 1)], saturated_int(c.f(3)), saturated_int(c.f(4)));
        }
        return Value::string(r);
    }
    if (id == Builtin::Strlen) return number(static_cast<double>(c.s(0).size()));
    if (id == Builtin::Substr) {
        std::string s = c.s(0);
        long start = static_cast<long>(c.f(1)), length = static_cast<long>(c.f(2));
        if (start < 1 || length < 0 || start - 1 + length > static_cast<long>(s.size())) {
            c.domain("range outside the string");
            return Value::string("");
        }
        return Value::string(s.substr(start - 1, length));
    }
    if (id == Builtin::Chr) {
        long code = static_cast<long>(c.f(0));
        if (code < 1 || code > 127) {
            c.domain("only ASCII codes 1..127 are supported");
            return Value::string("");
        }
        return Value::string(std::string(1, static_cast<char>(code)));
    }
    if (id == Builtin::Asc) {
        std::string s = c.s(0);
        return number(s.empty() ? 0.0 : static_cast<unsigned char>(s[0]));
    }
    if (id == Builtin::Val) {
        std::string s = c.s(0);
        char* end = nullptr;
        double x = std::strtod(s.c_str(), &end);
        return number(end == s.c_str() ? 0.0 : x);
    }
    if (id == Builtin::Strupr || id == Builtin::Strlwr) {
        std::string s = c.s(0);
        for (auto& ch : s) ch = id == Builtin::Strupr ? std::toupper(ch) : std::tolower(ch);
        return Value::string(s);
    }
    if (id == Builtin::Strcmp) {
        // POV's: the difference of the first characters that differ (here
        // bytes of the UTF-8 text), 0 when equal.
        const std::string a = c.s(0), b = c.s(1);
        std::size_t i = 0;
        while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
        const int left = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
        const int right = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
        return number(static_cast<double>(left - right));
    }
    if (id == Builtin::Datetime) {
        const std::string format = args.size() > 1 ? c.s(1) : "%Y-%m-%d %H:%M:%SZ";
        if (format.empty() || format.size() > kLongestDatetimeText) {
            c.domain(format.empty() ? "the format is empty"
                                    : "the format is longer than POV-Ray's " + std::to_string(kLongestDatetimeText) +
                                          " characters");
            return Value::string("");
        }
        const std::optional<std::string> text = datetime_text(c.f(0), format);
        if (!text) c.domain("the date is outside the years 1400 to 9999 (POV-Ray's range)");
        return Value::string(text.value_or(""));
    }
    if (id == Builtin::FileExists) {
        std::error_code ec;
        // Under --safe a path outside the allowed folders does not exist: the
        // scene must not learn what is on the disk outside.
        return number(allowed_file(c.s(0)) && std::filesystem::exists(c.s(0), ec) ? 1.0 : 0.0);
    }
    error(where.begin, "unknown function '" + name + "'");
    return Value::number(0.0);
}

}  // namespace lancer::parse
