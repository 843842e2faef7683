// The stack a parse runs on. Each macro call and nested parse (#debug's
// string, a macro's arguments) stacks a parser, and a sanitizer's frames are
// several times larger than a release build's: the default thread stack of
// 8 MiB overflowed under AddressSanitizer before the macro depth limit of
// 200. So a parse runs on a thread of its own with kParseStackBytes of
// stack (address space; only the pages used are ever touched), and
// parse_stack_nearly_full() lets the evaluator stop with a located error
// well before the end of it, whatever the frame sizes.
#pragma once

#include <cstddef>
#include <functional>

namespace lancer::parse {

constexpr std::size_t kParseStackBytes = std::size_t(256) << 20;

// Runs `work` on a thread with kParseStackBytes of stack and waits for it;
// an exception it throws is rethrown here. Runs it in place when no such
// thread can be made.
void run_on_parse_stack(const std::function<void()>& work);

// Whether the calling parse has used more than three quarters of its stack
// (false on a thread that run_on_parse_stack did not start).
bool parse_stack_nearly_full();

}  // namespace lancer::parse
