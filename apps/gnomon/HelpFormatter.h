// Help that fits 100 columns: CLI11's layout (names in a 30-column gutter, descriptions
// beside them) with the descriptions wrapped at word boundaries.
#pragma once

#include <CLI/CLI.hpp>
#include <sstream>
#include <string>

namespace gnomon::cli {

class HelpFormatter : public CLI::Formatter {
public:
    static constexpr std::size_t kColumns = 100;

    HelpFormatter() { column_width(30); }

    std::string make_option_desc(const CLI::Option* opt) const override {
        return wrap(CLI::Formatter::make_option_desc(opt));
    }
    std::string make_subcommand(const CLI::App* sub) const override {
        std::stringstream out;
        CLI::detail::format_help(out, sub->get_display_name(true), wrap(sub->get_description()),
                                 get_column_width());
        return out.str();
    }

    // `text` broken into lines of at most the width beside the gutter (a longer word keeps
    // its own line).
    std::string wrap(const std::string& text) const {
        const std::size_t width = kColumns - get_column_width();
        std::string out, line, word;
        std::istringstream words(text);
        while (words >> word) {
            if (!line.empty() && line.size() + 1 + word.size() > width) {
                out += line + "\n";
                line.clear();
            }
            line += (line.empty() ? "" : " ") + word;
        }
        return out + line;
    }
};

}  // namespace gnomon::cli
