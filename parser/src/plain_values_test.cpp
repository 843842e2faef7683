// A #declare'd plain expression is read without the grammar
// (plain_values.cpp): every value, message and side effect must be what the
// grammar gives for the same text (ParseOptions::plain_values false).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::all_diagnostics;
using test::parse_snippet;

const char* const kPrelude = R"(#declare S = seed(5);
#declare F = 1.5;
#declare N = -2;
#declare V = <1, -2, 3>;
#declare W = <0.5, 0.25>;
#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#declare T = "ab";
#declare B = on;
)";

// What the scene says about R (kind, components at full precision) and
// about the random stream after it, with every diagnostic.
std::string reading(const std::string& value, bool plain) {
    const std::string text = std::string(kPrelude) + "#declare R = " + value +
                             ";\n#debug R\n#debug vstr(5, R, \",\", 0, 17)\n"
                             "#declare Z = rand(S);\n#debug str(Z, 0, 17)\n";
    ParseOptions options;
    options.plain_values = plain;
    const ParseResult result = parse_snippet(text, "plain.pov", options);
    return std::string(result.ok() ? "ok\n" : "failed\n") + all_diagnostics(result);
}

TEST(ParserPlainValues, ReadAsTheGrammarReadsThem) {
    const std::vector<std::string> values = {
        "1",
        "-F",
        "+F",
        "!F",
        "!0",
        "--F",
        "- -F",
        // precedence and associativity
        "1 + 2 * 3",
        "(1 + 2) * 3",
        "8 / 4 / 2",
        "8 - 4 - 2",
        "2 * -F + 1",
        "-F * 2",
        "-V.x * 2",
        "!F * 2",
        "1 < 2",
        "2 <= 2",
        "3 > 4",
        "3 >= 4",
        "F = 1.5",
        "F != 1.5",
        "1 < 2 < 3",
        "1 + 1 = 2",
        "1 & 0",
        "1 | 0",
        "0 | 1 & 0",
        "1 = 1 & 2 > 1",
        "!F | F",
        "F > 1 ? 10 : 20",
        "0 ? 1 : 0 ? 2 : 3",
        "1 ? 0 ? 4 : 5 : 6",
        "F ? V : 2 * V",
        "0 | 1 ? 7 : 8",
        "F < 2 ? rand(S) : rand(S)",
        // vectors and components
        "<1, 2, 3>",
        "<F, N, F + N>",
        "<F, N,>",
        "<1, 2, 3, 4, 5>",
        "<-F, (1 < 2), 3>",
        "V * 2 + <1, 1, 1>",
        "V + F",
        "F * V",
        "V / 2",
        "<V.x, V.y, V.z>",
        "V.z",
        "W.u + W.v",
        "C.red + C.filter + C.transmit",
        "C.gray",
        "C.grey",
        "<1, 2, 3, 4>.t",
        "V.x.x",
        "(V).y",
        "<(F), (N)>",
        "<<1,2,3>.x, 2>",
        // constants and calls
        "pi",
        "x + y * 2 + z * 3",
        "B",
        "on",
        "true + 1",
        "clock",
        "version",
        "image_width",
        "sin(F) + cos(F) * tan(F)",
        "pow(2, 10)",
        "max(1, F, 3, N)",
        "min(V.x, V.y)",
        "vlength(V)",
        "vnormalize(V)",
        "vcross(V, x)",
        "vdot(V, V)",
        "vrotate(V, <0, 90, 0>)",
        "vaxis_rotate(V, y, 45)",
        "mod(7, 3) + div(7, 3) + int(-2.5) + floor(-2.5) + ceil(-2.5)",
        "abs(N) + sqr(N) + sqrt(F)",
        "rand(S) + rand(S) * 2",
        "<rand(S), rand(S), rand(S)> * 100",
        "select(N, 1, 2)",
        "select(0, 1, 2, 3)",
        "degrees(pi) + radians(180)",
        "atan2(1, 2) + exp(1) + log(100) + ln(10)",
        "bitwise_and(12, 10)",
        "strlen(T) + asc(T)",
        "val(\"3.25\")",
        "strcmp(T, \"ac\")",
        // strings
        "T",
        "\"x\"",
        "concat(T, \"cd\", str(F, 0, 3))",
        "T = \"ab\"",
        "T != \"ab\"",
        "strupr(T)",
        "substr(\"hello\", 2, 3)",
        "chr(65)",
        // errors: the same message at the same place
        "1 / 0",
        "V / 0",
        "sqrt(-1)",
        "log(0)",
        "asin(2)",
        "pow(0, -1)",
        "T + 1",
        "V + T",
        "F.x",
        "Undeclared + 1",
        "sin()",
        "sin(1, 2)",
        "rand(99)",
        "V.q",
        "1 +",
        "(1",
        "<1, 2",
        "1 ? 2",
        "F F",
        "<1 < 2, 3>",
        "<1, 2 > 3>",
        "rgb 1",
        "T[0]",
        "dimensions(T)",
        "defined(F)",
        "now > 0",
        "mod(1, 0)",
        "vnormalize(<0,0,0>)",
        "substr(T, 5, 1)",
        "chr(0)",
    };
    for (const std::string& value : values) {
        SCOPED_TRACE(value);
        EXPECT_EQ(reading(value, true), reading(value, false));
    }
}

TEST(ParserPlainValues, DeclarationsAroundTheValueAreTheGrammars) {
    // #local in a macro, a value that a macro writes, no ';', a value
    // ending in a macro's text, deprecated names, nested loops, and the
    // conditions of #if, #elseif and #while.
    const std::vector<std::string> scenes = {
        "#macro M(A) #local Q = A * 2; Q #end #declare R = M(3); #debug str(R, 0, 3)",
        "#macro Two() 2 #end #declare R = 1 + Two(); #debug str(R, 0, 3)",
        "#declare R = 1 #debug str(R, 0, 3)",
        "#declare deprecated once \"old\" D = 1; #declare R = D + 1; #declare R = D * 2; #debug str(R, 0, 3)",
        "#declare I = 0; #declare Sum = 0; #while (I < 5) #declare J = 0; #while (J < I) "
        "#declare Sum = Sum + I * J; #declare J = J + 1; #end #declare I = I + 1; #end #debug str(Sum, 0, 0)",
        "#for (K, 1, 3) #local L = K * K; #debug str(L, 0, 0) #end",
        "#declare A = array[3] {1, 2, 3} #declare R = A[1] + 1; #debug str(R, 0, 0)",
        "#declare R = <1, 2, 3>\n#declare Q = R.x; #debug str(Q, 0, 0)",
        "#declare P = function(u) { u * 2 } #declare R = P(3); #debug str(R, 0, 0)",
        "#declare R = 1; #declare R = R + R; #undef R #declare R = 3; #debug str(R, 0, 0)",
        // conditions, read with their parentheses
        "#declare A = 2; #if (A > 1 & A < 3) #debug \"in\" #else #debug \"out\" #end",
        "#declare A = 2; #if (A = 1) #debug \"one\" #elseif (A = 2) #debug \"two\" #end",
        "#if ((1 + 1) * 2 = 4) #debug \"yes\" #end",
        "#if (\"a\") #end",
        "#if (1 / 0) #end",
        "#if (Nope < 3) #end",
        "#if (1 < 2 #end",
        "#if 1 #end",
        "#declare I = 0; #while (I < 3 & rand(seed(1)) >= 0) #declare I = I + 1; #end #debug str(I, 0, 0)",
        "#declare I = 0; #while (I < 3) #declare I = I + 1; #end #if (I = 3) #debug \"three\" #end",
        "#declare V = <1, 2, 3>; #if (V.y = 2) #debug \"y\" #end #if (V) #end",
    };
    for (const std::string& scene : scenes) {
        SCOPED_TRACE(scene);
        auto read = [&scene](bool plain) {
            ParseOptions options;
            options.plain_values = plain;
            const ParseResult result = parse_snippet(scene, "plain.pov", options);
            return std::string(result.ok() ? "ok\n" : "failed\n") + all_diagnostics(result);
        };
        EXPECT_EQ(read(true), read(false));
    }
}

TEST(ParserPlainValues, WriteItemsAreWrittenAsTheGrammarWritesThem) {
    const std::string items[] = {
        R"("a", 1.5, <1, 2, 3>, "\n")",
        R"("tri{", "<", str(V.x, 0, 16), ",", str(V.y * 2, 0, 3), ">", "}", "\n")",
        R"(V * 2 + 1, -F, F > 1, rgb 1, C)",
        R"("x" "y", 2)",  // no comma: the grammar reads on
        R"(1 / 0, "after")",
        R"(sphere { 0, 1 })",
        R"(uint8 65, "B")",
    };
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("lancer_plain_write_" + std::to_string(::getpid()) + ".txt");
    for (const std::string& list : items) {
        SCOPED_TRACE(list);
        auto written = [&](bool plain) {
            ParseOptions options;
            options.plain_values = plain;
            const std::string scene = std::string(kPrelude) + "#fopen Out \"" + file.string() +
                                      "\" write\n#write (Out, " + list + ")\n#fclose Out\n";
            const ParseResult result = parse_snippet(scene, "plain.pov", options);
            std::ifstream in(file, std::ios::binary);
            std::ostringstream content;
            content << in.rdbuf();
            return std::string(result.ok() ? "ok\n" : "failed\n") + all_diagnostics(result) + content.str();
        };
        EXPECT_EQ(written(true), written(false));
        std::filesystem::remove(file);
    }
}

}  // namespace
}  // namespace lancer
