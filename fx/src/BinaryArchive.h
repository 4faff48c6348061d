// BinaryArchive: the little-endian encoding of compiled effect files (fx/CompiledEffectFile.h), one
// writer and one reader over the same calls, so that a struct's fields are listed once
// (CompiledEffectFields.h) and a field added there is written and read alike.
//
// Encoding: integers and enums as fixed-width little-endian (bool and uint8_t one byte, other integers
// and enums four or eight bytes; an enum with an EnumByName specialization as its enumerator's name), floats
// by their IEEE bit pattern, strings and vectors as a uint32_t count followed by the elements, an optional as
// a byte (0 absent, 1 present) and the value. The reader never reads past its input: a count larger than the
// bytes left, or a read past the end, fails it
// (`failed()`, with the diagnostic that says what it was reading, and the byte offset) and every later read
// yields zeros.
#pragma once

#include <fx/Diagnostics.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fx::detail {

// The largest enumerator a reader accepts for each enum it reads by number (CompiledEffectFields.h
// specializes it).
template <class E>
struct EnumLimit;

// Enums stored by their enumerators' names, not numbers: the long tables that grow with the language
// (diagnostic ids, render states), so that an enumerator inserted mid-table does not change what an older
// file means. A specialization provides `static std::string_view name(E)` and
// `static std::optional<E> find(std::string_view)`.
template <class E>
struct EnumByName : std::false_type {};

class BinaryWriter {
public:
    static constexpr bool kReading = false;

    template <class T>
    void operator()(const T& value) {
        if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, uint8_t>) {
            mBytes.push_back(static_cast<char>(value));
        } else if constexpr (EnumByName<T>::value) {
            (*this)(std::string(EnumByName<T>::name(value)));
        } else if constexpr (std::is_enum_v<T>) {
            integer(static_cast<uint32_t>(value), 4);
        } else if constexpr (std::is_same_v<T, float>) {
            uint32_t bits;
            std::memcpy(&bits, &value, 4);
            integer(bits, 4);
        } else if constexpr (std::is_same_v<T, double>) {
            uint64_t bits;
            std::memcpy(&bits, &value, 8);
            integer(bits, 8);
        } else if constexpr (std::is_integral_v<T>) {
            integer(static_cast<uint64_t>(value), sizeof(T) <= 4 ? 4 : 8);
        } else if constexpr (std::is_same_v<T, std::string>) {
            integer(value.size(), 4);
            mBytes.append(value);
        } else {
            fields(*this, const_cast<T&>(value));  // the writer only reads through the shared field list
        }
    }
    template <class T>
    void operator()(const std::vector<T>& values) {
        integer(values.size(), 4);
        for (const T& value : values) (*this)(value);
    }
    template <class T>
    void operator()(const std::optional<T>& value) {
        (*this)(value.has_value());
        if (value) (*this)(*value);
    }
    template <class A, class B>
    void operator()(const std::pair<A, B>& value) {
        (*this)(value.first);
        (*this)(value.second);
    }
    template <class T, size_t N>
    void operator()(const T (&values)[N]) {
        for (const T& value : values) (*this)(value);
    }
    // Several fields in order: `archive(a, b, c)`.
    template <class T, class U, class... Rest>
    void operator()(const T& first, const U& second, const Rest&... rest) {
        (*this)(first);
        (*this)(second, rest...);
    }

    void require(bool, DiagId) {}  // the writer writes what the compiler made
    const std::string& bytes() const { return mBytes; }

private:
    void integer(uint64_t value, int width) {
        for (int i = 0; i < width; ++i) mBytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
    }
    std::string mBytes;
};

class BinaryReader {
public:
    static constexpr bool kReading = true;

    explicit BinaryReader(std::string_view bytes) : mBytes(bytes) {}

    template <class T>
    void operator()(T& value) {
        if constexpr (std::is_same_v<T, bool>) {
            const uint64_t byte = integer(1, "a flag");
            if (byte > 1) fail(DiagId::CompiledEffectFlagInvalid);
            value = byte == 1;
        } else if constexpr (std::is_same_v<T, uint8_t>) {
            value = static_cast<uint8_t>(integer(1, "a byte"));
        } else if constexpr (EnumByName<T>::value) {
            std::string name;
            (*this)(name);
            if (const std::optional<T> found = EnumByName<T>::find(name)) {
                value = *found;
            } else {
                fail(DiagId::CompiledEffectEnumeratorUnknown, {name});
                value = T{};
            }
        } else if constexpr (std::is_enum_v<T>) {
            const uint64_t raw = integer(4, "an enumerator");
            if (raw > static_cast<uint64_t>(EnumLimit<T>::kLast)) {
                fail(DiagId::CompiledEffectEnumeratorOutOfRange, {std::to_string(raw)});
                value = T{};
            } else {
                value = static_cast<T>(raw);
            }
        } else if constexpr (std::is_same_v<T, float>) {
            const uint32_t bits = static_cast<uint32_t>(integer(4, "a number"));
            std::memcpy(&value, &bits, 4);
        } else if constexpr (std::is_same_v<T, double>) {
            const uint64_t bits = integer(8, "a number");
            std::memcpy(&value, &bits, 8);
        } else if constexpr (std::is_integral_v<T>) {
            const uint64_t raw = integer(sizeof(T) <= 4 ? 4 : 8, "an integer");
            value = static_cast<T>(raw);
        } else if constexpr (std::is_same_v<T, std::string>) {
            const size_t size = count("a string");
            value.assign(mBytes.substr(mOffset, size));
            mOffset += size;
        } else {
            fields(*this, value);
        }
    }
    template <class T>
    void operator()(std::vector<T>& values) {
        // Every element takes at least one byte: a count beyond the bytes left is a corrupt file, not an
        // allocation to attempt.
        const size_t size = count("a list");
        values.clear();
        values.resize(size);
        for (T& value : values) (*this)(value);
    }
    template <class T>
    void operator()(std::optional<T>& value) {
        bool present = false;
        (*this)(present);
        value.reset();
        if (present) (*this)(value.emplace());
    }
    template <class A, class B>
    void operator()(std::pair<A, B>& value) {
        (*this)(value.first);
        (*this)(value.second);
    }
    template <class T, size_t N>
    void operator()(T (&values)[N]) {
        for (T& value : values) (*this)(value);
    }
    template <class T, class U, class... Rest>
    void operator()(T& first, U& second, Rest&... rest) {
        (*this)(first);
        (*this)(second, rest...);
    }

    // A field the shared list checks as it reads: fails the read with `id` unless `ok`.
    void require(bool ok, DiagId id) {
        if (!ok) fail(id);
    }
    bool failed() const { return mError.has_value(); }
    // What could not be read: the diagnostic, its arguments ending in the byte of the content where the read
    // stood.
    DiagId error() const { return *mError; }
    std::vector<std::string> errorArgs() const {
        std::vector<std::string> args = mErrorArgs;
        args.push_back(std::to_string(mErrorOffset));
        return args;
    }
    bool atEnd() const { return mOffset == mBytes.size(); }
    size_t offset() const { return mOffset; }

private:
    void fail(DiagId id, std::vector<std::string> args = {}) {
        if (!mError) {
            mError = id;
            mErrorArgs = std::move(args);
            mErrorOffset = mOffset;
        }
        mOffset = mBytes.size();
    }
    uint64_t integer(size_t width, const char* what) {
        if (failed()) return 0;
        if (mBytes.size() - mOffset < width) {
            fail(DiagId::CompiledEffectContentEndsInValue, {what});
            return 0;
        }
        uint64_t value = 0;
        for (size_t i = 0; i < width; ++i)
            value |= static_cast<uint64_t>(static_cast<uint8_t>(mBytes[mOffset + i])) << (8 * i);
        mOffset += width;
        return value;
    }
    size_t count(const char* what) {
        const uint64_t size = integer(4, what);
        if (size > mBytes.size() - mOffset) {
            fail(DiagId::CompiledEffectLengthBeyondContent, {what, std::to_string(size)});
            return 0;
        }
        return static_cast<size_t>(size);
    }

    std::string_view mBytes;
    size_t mOffset = 0;
    std::optional<DiagId> mError;
    std::vector<std::string> mErrorArgs;
    size_t mErrorOffset = 0;
};

}  // namespace fx::detail
