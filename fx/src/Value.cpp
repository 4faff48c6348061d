// Value: constructors for host-side parameter values.
#include <fx/Value.h>

namespace fx {

namespace {
TypeDesc scalarType(BaseType base) {
    TypeDesc t;
    t.base = base;
    return t;
}
// Component count without relying on TypeDesc's out-of-line helpers (defined with the AST).
size_t countComponents(const TypeDesc& type) {
    size_t n = static_cast<size_t>(type.rows) * static_cast<size_t>(type.cols);
    for (int d : type.arrayDims) n *= static_cast<size_t>(d > 0 ? d : 1);
    return n;
}
}  // namespace

Value Value::scalar(float v) {
    Value out;
    out.type = scalarType(BaseType::Float);
    out.data = {v};
    return out;
}

Value Value::boolean(bool v) {
    Value out;
    out.type = scalarType(BaseType::Bool);
    out.data = {v ? 1.0f : 0.0f};
    return out;
}

Value Value::integer(int v) {
    Value out;
    out.type = scalarType(BaseType::Int);
    out.data = {static_cast<float>(v)};
    return out;
}

Value Value::vector(std::vector<float> components) {
    Value out;
    out.type.base = BaseType::Float;
    out.type.shape = components.size() == 1 ? Shape::Scalar : Shape::Vector;
    out.type.cols = static_cast<int>(components.size());
    out.data = std::move(components);
    return out;
}

Value Value::matrix(int rows, int cols, std::vector<float> rowMajorData) {
    Value out;
    out.type.base = BaseType::Float;
    out.type.shape = Shape::Matrix;
    out.type.rows = rows;
    out.type.cols = cols;
    rowMajorData.resize(static_cast<size_t>(rows * cols), 0.0f);
    out.data = std::move(rowMajorData);
    return out;
}

Value Value::text(std::string s) {
    Value out;
    out.type = scalarType(BaseType::String);
    out.string = std::move(s);
    return out;
}

Value zeroValue(const TypeDesc& type) {
    Value out;
    out.type = type;
    bool numeric = type.base == BaseType::Bool || type.base == BaseType::Int || type.base == BaseType::UInt ||
                   type.base == BaseType::Half || type.base == BaseType::Float ||
                   type.base == BaseType::Double;
    if (numeric) out.data.assign(countComponents(type), 0.0f);
    return out;
}

}  // namespace fx
