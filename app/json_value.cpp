#include "json_value.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hlens {

Value vec2(Vec2 p) { return Value::array().push(Value::number(p.x)).push(Value::number(p.y)); }
Value vec3(const Vec3& p) {
    return Value::array().push(Value::number(p.x)).push(Value::number(p.y)).push(Value::number(p.z));
}

std::string format_double(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

static void json_string(std::string& out, const std::string& s) {
    out += '"';
    for (unsigned char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20 || c == 0x7f) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += char(c);  // UTF-8 passes through unchanged
                }
        }
    }
    out += '"';
}


void to_json(std::string& out, const Value& v) {
    switch (v.kind) {
        case Value::Null: out += "null"; break;
        case Value::Bool: out += v.b ? "true" : "false"; break;
        case Value::Int: out += std::to_string(v.i); break;
        case Value::Num: out += std::isfinite(v.d) ? format_double(v.d, 17) : "null"; break;
        case Value::Str: json_string(out, v.s); break;
        case Value::Arr:
            out += '[';
            for (size_t k = 0; k < v.items.size(); ++k) {
                if (k) out += ", ";
                to_json(out, v.items[k]);
            }
            out += ']';
            break;
        case Value::Obj:
            out += '{';
            for (size_t k = 0; k < v.fields.size(); ++k) {
                if (k) out += ", ";
                json_string(out, v.fields[k].first);
                out += ": ";
                to_json(out, v.fields[k].second);
            }
            out += '}';
            break;
    }
}

// The same value for people: numbers with 10 digits, number lists as (x, y), objects as k=v.
void to_text(std::string& out, const Value& v) {
    switch (v.kind) {
        case Value::Null: out += "-"; break;
        case Value::Bool: out += v.b ? "yes" : "no"; break;
        case Value::Int: out += std::to_string(v.i); break;
        case Value::Num: out += std::isfinite(v.d) ? format_double(v.d, 10) : (v.d > 0 ? "inf" : "nan"); break;
        case Value::Str: out += v.s; break;
        case Value::Arr: {
            bool numeric = !v.items.empty() && std::all_of(v.items.begin(), v.items.end(), [](const Value& x) {
                return x.kind == Value::Num || x.kind == Value::Int;
            });
            out += numeric ? '(' : '[';
            for (size_t k = 0; k < v.items.size(); ++k) {
                if (k) out += numeric ? ", " : " ";
                to_text(out, v.items[k]);
            }
            out += numeric ? ')' : ']';
            break;
        }
        case Value::Obj:
            out += '{';
            for (size_t k = 0; k < v.fields.size(); ++k) {
                if (k) out += ' ';
                out += v.fields[k].first + '=';
                to_text(out, v.fields[k].second);
            }
            out += '}';
            break;
    }
}

std::string to_json(const Value& v) {
    std::string out;
    to_json(out, v);
    return out;
}

const Value* find_field(const Value& obj, const std::string& key) {
    for (const auto& [k, v] : obj.fields)
        if (k == key) return &v;
    return nullptr;
}

Value* find_field(Value& obj, const std::string& key) {
    return const_cast<Value*>(find_field(static_cast<const Value&>(obj), key));
}

}  // namespace hlens
