// Value: an effect parameter's value on the host (a number, vector, matrix, array or string).
#pragma once

#include <fx/Types.h>

#include <string>
#include <vector>

namespace fx {

struct Value {
    TypeDesc type;
    // Numeric components in HLSL element order: vectors x,y,z,w; matrices row by row (m[r][c] is
    // data[r * cols + c]); arrays element after element. Bools and ints are stored as floats.
    // A D3DX-style transform (row vectors, translation in the fourth row) has data[12..14] = translation;
    // a glm::mat4 holding the same transform (column vectors) has exactly this memory layout.
    std::vector<float> data;
    std::string string;  // String values

    static Value scalar(float v);
    static Value boolean(bool v);
    static Value integer(int v);
    static Value vector(std::vector<float> components);
    static Value matrix(int rows, int cols, std::vector<float> rowMajorData);
    static Value text(std::string s);

    float asFloat() const { return data.empty() ? 0.0f : data[0]; }
    bool asBool() const { return !data.empty() && data[0] != 0.0f; }
    // Saturating: NaN gives 0 and values beyond int's range clamp (a plain cast of those is undefined
    // behaviour, and a fuzzed `int MipLevels = 1e30;` or `LoopByCount=Count` with Count = 0.0/0.0 reaches
    // it).
    int asInt() const {
        if (data.empty() || !(data[0] == data[0])) return 0;
        if (data[0] >= 2147483648.0f) return 2147483647;
        if (data[0] < -2147483648.0f) return -2147483647 - 1;
        return static_cast<int>(data[0]);
    }
};

// A zero value of the given type (strings empty).
Value zeroValue(const TypeDesc& type);

}  // namespace fx
