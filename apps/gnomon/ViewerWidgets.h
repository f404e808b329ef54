// Small Dear ImGui helpers the viewer's panels share: tooltips and enum combo boxes.
#pragma once

#include <imgui.h>

#include <initializer_list>
#include <string>

namespace gnomon::cli::viewer {

// The last item's tooltip. Callers that build the text check ImGui::IsItemHovered() first,
// so nothing is formatted on frames where no tooltip shows.
inline void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}
inline void tooltip(const std::string& text) {
    tooltip(text.c_str());
}

template <typename E>
bool enumCombo(const char* label, E& value, std::initializer_list<E> values) {
    bool changed = false;
    if (ImGui::BeginCombo(label, toString(value))) {
        for (E v : values) {
            if (ImGui::Selectable(toString(v), v == value)) {
                changed = v != value;
                value = v;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

}  // namespace gnomon::cli::viewer
