// JsonSchema: the check of a results document (results.json of bench and tune) against
// docs/results.schema.json, for the command-line tests and the report writer's.
#pragma once

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shadowfx::test {

// The subset of JSON Schema the checked-in schema uses: type (one or a list), required, properties,
// items, enum, minimum and local $ref. Returns the first violation, with its JSON path.
inline ::testing::AssertionResult validate(const nlohmann::json& value, const nlohmann::json& schema,
                                           const nlohmann::json& root, const std::string& path) {
    if (schema.contains("$ref")) {
        const std::string ref = schema["$ref"];
        const std::string prefix = "#/$defs/";
        if (ref.rfind(prefix, 0) != 0) return ::testing::AssertionFailure() << "unsupported $ref " << ref;
        return validate(value, root["$defs"][ref.substr(prefix.size())], root, path);
    }
    if (schema.contains("type")) {
        const std::vector<std::string> types =
            schema["type"].is_array() ? schema["type"].get<std::vector<std::string>>()
                                      : std::vector<std::string>{schema["type"].get<std::string>()};
        bool matches = false;
        for (const std::string& type : types) {
            matches = matches || (type == "object" && value.is_object()) ||
                      (type == "array" && value.is_array()) || (type == "string" && value.is_string()) ||
                      (type == "boolean" && value.is_boolean()) || (type == "null" && value.is_null()) ||
                      (type == "number" && value.is_number()) ||
                      (type == "integer" && value.is_number_integer());
        }
        if (!matches)
            return ::testing::AssertionFailure()
                   << path << ": " << value.dump() << " is not " << schema["type"].dump();
    }
    if (schema.contains("enum")) {
        bool found = false;
        for (const nlohmann::json& allowed : schema["enum"]) found = found || allowed == value;
        if (!found)
            return ::testing::AssertionFailure()
                   << path << ": " << value.dump() << " not in " << schema["enum"].dump();
    }
    if (schema.contains("minimum") && value.is_number() &&
        value.get<double>() < schema["minimum"].get<double>())
        return ::testing::AssertionFailure()
               << path << ": " << value.dump() << " < minimum " << schema["minimum"].dump();
    if (value.is_object()) {
        if (schema.contains("required"))
            for (const nlohmann::json& key : schema["required"])
                if (!value.contains(key.get<std::string>()))
                    return ::testing::AssertionFailure()
                           << path << ": required key '" << key.get<std::string>() << "' missing";
        if (schema.contains("properties"))
            for (const auto& [key, sub] : schema["properties"].items())
                if (value.contains(key))
                    if (auto r = validate(value[key], sub, root, path + "." + key); !r) return r;
    }
    if (value.is_array() && schema.contains("items"))
        for (size_t i = 0; i < value.size(); ++i)
            if (auto r = validate(value[i], schema["items"], root, path + "[" + std::to_string(i) + "]"); !r)
                return r;
    return ::testing::AssertionSuccess();
}

}  // namespace shadowfx::test
