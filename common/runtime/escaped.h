// Text from outside (a name in a command, a file name, a peer's string)
// made safe to print on one line: a newline in it cannot forge a log line,
// an escape sequence cannot redraw the terminal.
#pragma once

#include <string>

namespace ws {

// `text` with every control character written as \n, \r, \t or \xNN and a
// backslash as \\.
std::string Escaped(const std::string& text);

// 'text', escaped: how a name from outside appears in a message.
std::string Quoted(const std::string& text);

}  // namespace ws
