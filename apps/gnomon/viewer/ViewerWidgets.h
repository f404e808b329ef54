// Small Dear ImGui helpers the viewer's panels share: tooltips, enum combo boxes, and the
// widget of a render option made from its schema entry (so its range is the CLI's).
#pragma once

#include <imgui.h>

#include <cmath>
#include <initializer_list>
#include <string>

#include "gnomon/OptionSchema.h"

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

// The option's widget: a checkbox, a combo of its choices, an odd-only or "auto"-at-0 integer
// slider, or a number slider over its range (logarithmic where the range spans decades).
// True when the value changed. (The viewer gives the size, map-size and light-only widgets of
// their own: Viewer::optionControl.)
inline bool optionWidget(const OptionSpec& spec, RenderOptions& o) {
    const double value = spec.get(o);
    switch (spec.kind) {
        case OptionKind::Switch: {
            bool on = value != 0.0;
            if (!ImGui::Checkbox(spec.name, &on)) return false;
            spec.set(o, on ? 1.0 : 0.0);
            return true;
        }
        case OptionKind::Choice: {
            int index = int(value);
            bool changed = false;
            if (ImGui::BeginCombo(spec.name, spec.choices.at(std::size_t(index)).c_str())) {
                for (std::size_t i = 0; i < spec.choices.size(); ++i) {
                    if (ImGui::Selectable(spec.choices[i].c_str(), int(i) == index)) {
                        changed = int(i) != index;
                        index = int(i);
                    }
                }
                ImGui::EndCombo();
            }
            if (changed) spec.set(o, double(index));
            return changed;
        }
        case OptionKind::Integer: {
            if (spec.odd) {  // a slider over the odd values only
                int half = (int(value) - 1) / 2;
                const int lo = (int(spec.min) - 1) / 2, hi = (int(spec.max) - 1) / 2;
                if (!ImGui::SliderInt(spec.name, &half, lo, hi,
                                      std::to_string(2 * half + 1).c_str()))
                    return false;
                spec.set(o, double(2 * half + 1));
                return true;
            }
            int v = int(value);
            const int lo = spec.zeroAllowed ? 0 : int(spec.min);
            if (!ImGui::SliderInt(spec.name, &v, lo, int(spec.max),
                                  v == 0 && *spec.zeroName ? spec.zeroName : "%d"))
                return false;
            spec.set(o, double(v == 0 || v >= spec.min ? v : int(spec.min)));
            return true;
        }
        case OptionKind::Real: {
            float v = float(value);
            if (!std::isfinite(float(spec.min)) || !std::isfinite(float(spec.max))) {
                // Unbounded (time): dragged, not a slider over all the floats.
                const std::string format =
                    std::string("%.4g") + (*spec.unit ? " " : "") + spec.unit;
                if (!ImGui::DragFloat(spec.name, &v, 0.05f, 0.0f, 0.0f, format.c_str()))
                    return false;
                spec.set(o, double(v));
                return true;
            }
            const float lo = float(spec.min);
            // [min, max): the largest float below max.
            const float hi =
                spec.maxExclusive ? std::nextafter(float(spec.max), lo) : float(spec.max);
            const bool decades = spec.min >= 0.0 && spec.max >= 1000.0 * std::max(spec.min, 1e-3);
            if (!ImGui::SliderFloat(spec.name, &v, lo, hi, "%.5g",
                                    decades ? ImGuiSliderFlags_Logarithmic : 0))
                return false;
            spec.set(o, double(v));
            return true;
        }
        case OptionKind::Size:
            return false;
    }
    return false;
}

}  // namespace gnomon::cli::viewer
