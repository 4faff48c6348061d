// ConformanceReport: see ConformanceReport.h.
#include <report/ConformanceReport.h>
#include <report/XmlText.h>

#include <algorithm>
#include <map>

namespace report {

const char* checkOutcomeName(CheckOutcome outcome) {
    switch (outcome) {
        case CheckOutcome::Pass:
            return "PASS";
        case CheckOutcome::QualityWarning:
            return "QUALITY_WARNING";
        case CheckOutcome::NotSupported:
            return "NOT_SUPPORTED";
        case CheckOutcome::Fail:
            return "FAIL";
    }
    return "?";
}

CheckOutcome judgeBelow(double measured, double bound) {
    if (!(measured < bound)) return CheckOutcome::Fail;  // NaN fails too
    return measured > kWarnFraction * bound ? CheckOutcome::QualityWarning : CheckOutcome::Pass;
}

void writeEffectSummary(std::ostream& out, const std::vector<CheckRow>& rows) {
    struct EffectStatus {
        std::string failure;  // technique: first compile or render error
        std::string blank;    // technique: first blank frame
    };
    std::vector<std::string> order;
    std::map<std::string, EffectStatus> status;
    for (const CheckRow& r : rows) {
        if (!status.count(r.effect)) order.push_back(r.effect);
        EffectStatus& s = status[r.effect];
        if (r.outcome != CheckOutcome::Fail || (r.check != "compile" && r.check != "render")) continue;
        std::string& slot = r.detail.rfind(kBlankFrame, 0) == 0 ? s.blank : s.failure;
        if (slot.empty()) slot = (r.technique == "-" ? "" : r.technique + ": ") + r.detail;
    }
    size_t drawn = 0, blank = 0, failed = 0;
    out << "\n";
    for (const std::string& effect : order) {
        const EffectStatus& s = status[effect];
        if (!s.failure.empty()) {
            ++failed;
            out << effect << ": failed: " << s.failure.substr(0, s.failure.find('\n')) << "\n";
        } else if (!s.blank.empty()) {
            ++blank;
            out << effect << ": blank: " << s.blank << "\n";
        } else {
            ++drawn;
            out << effect << ": drawn\n";
        }
    }
    out << order.size() << (order.size() == 1 ? " effect: " : " effects: ") << drawn << " drawn, " << blank
        << " blank, " << failed << " failed\n";
}

void writeCheckTable(std::ostream& out, const std::vector<CheckRow>& rows) {
    const std::vector<std::string> header{"RESULT", "BACKEND", "EFFECT", "TECHNIQUE",
                                          "SCENE",  "CHECK",   "DETAIL"};
    std::vector<size_t> widths(header.size());
    auto cells = [](const CheckRow& r) {
        return std::vector<std::string>{
            checkOutcomeName(r.outcome), r.backend, r.effect, r.technique, r.scene, r.check, r.detail};
    };
    for (size_t c = 0; c < header.size(); ++c) widths[c] = header[c].size();
    for (const CheckRow& r : rows) {
        const std::vector<std::string> row = cells(r);
        for (size_t c = 0; c + 1 < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    }
    auto print = [&](const std::vector<std::string>& row) {
        for (size_t c = 0; c < row.size(); ++c) {
            out << row[c];
            if (c + 1 < row.size()) out << std::string(widths[c] - row[c].size() + 2, ' ');
        }
        out << "\n";
    };
    print(header);
    for (const CheckRow& r : rows) print(cells(r));
}

void writeJunit(std::ostream& xml, const std::vector<CheckRow>& rows) {
    std::vector<std::string> effects;
    for (const CheckRow& r : rows)
        if (std::find(effects.begin(), effects.end(), r.effect) == effects.end()) effects.push_back(r.effect);
    auto count = [&](const std::string* effect, CheckOutcome outcome) {
        return std::count_if(rows.begin(), rows.end(), [&](const CheckRow& r) {
            return (!effect || r.effect == *effect) && r.outcome == outcome;
        });
    };
    auto total = [&](const std::string* effect) {
        return std::count_if(rows.begin(), rows.end(),
                             [&](const CheckRow& r) { return !effect || r.effect == *effect; });
    };
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml << "<testsuites name=\"shadowfx check\" tests=\"" << total(nullptr) << "\" failures=\""
        << count(nullptr, CheckOutcome::Fail) << "\" skipped=\"" << count(nullptr, CheckOutcome::NotSupported)
        << "\" errors=\"0\">\n";
    for (const std::string& effect : effects) {
        xml << "  <testsuite name=\"" << xmlEscape(effect) << "\" tests=\"" << total(&effect)
            << "\" failures=\"" << count(&effect, CheckOutcome::Fail) << "\" skipped=\""
            << count(&effect, CheckOutcome::NotSupported) << "\" errors=\"0\">\n";
        for (const CheckRow& r : rows) {
            if (r.effect != effect) continue;
            xml << "    <testcase classname=\"" << xmlEscape(r.effect + "." + r.technique) << "\" name=\""
                << xmlEscape(r.scene + "." + r.check + "[" + r.backend + "]") << "\"";
            switch (r.outcome) {
                case CheckOutcome::Pass:
                    xml << "/>\n";
                    break;
                case CheckOutcome::QualityWarning:
                    xml << ">\n      <system-out>QUALITY_WARNING: " << xmlEscape(r.detail)
                        << "</system-out>\n    </testcase>\n";
                    break;
                case CheckOutcome::NotSupported:
                    xml << ">\n      <skipped message=\"NOT_SUPPORTED: " << xmlEscape(r.detail)
                        << "\"/>\n    </testcase>\n";
                    break;
                case CheckOutcome::Fail:
                    xml << ">\n      <failure type=\"FAIL\" message=\"" << xmlEscape(r.detail) << "\">"
                        << xmlEscape(r.detail) << "</failure>\n    </testcase>\n";
                    break;
            }
        }
        xml << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
}

void writeCheckCounts(std::ostream& out, const std::vector<CheckRow>& rows) {
    std::map<CheckOutcome, size_t> counts;
    for (const CheckRow& r : rows) ++counts[r.outcome];
    out << rows.size() << " checks: " << counts[CheckOutcome::Pass] << " PASS, "
        << counts[CheckOutcome::QualityWarning] << " QUALITY_WARNING, " << counts[CheckOutcome::NotSupported]
        << " NOT_SUPPORTED, " << counts[CheckOutcome::Fail] << " FAIL\n";
}

}  // namespace report
