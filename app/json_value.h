// A tiny JSON value for the reports of hlens-cli and the Python module (app/report.h builds them):
// objects keep their fields in insertion order; doubles are written with 17 significant digits so
// they read back bit-exactly.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <hlens/vec.h>

namespace hlens {

struct Value {
    enum Kind { Null, Bool, Int, Num, Str, Arr, Obj } kind = Null;
    bool b = false;
    long long i = 0;
    double d = 0;
    std::string s;
    std::vector<Value> items;                            // Arr
    std::vector<std::pair<std::string, Value>> fields;   // Obj, in insertion order

    Value() = default;
    static Value boolean(bool v) { Value r; r.kind = Bool; r.b = v; return r; }
    static Value integer(long long v) { Value r; r.kind = Int; r.i = v; return r; }
    static Value number(double v) { Value r; r.kind = Num; r.d = v; return r; }   // non-finite: null
    static Value string(std::string v) { Value r; r.kind = Str; r.s = std::move(v); return r; }
    static Value array() { Value r; r.kind = Arr; return r; }
    static Value object() { Value r; r.kind = Obj; return r; }

    Value& add(const std::string& key, Value v) { fields.emplace_back(key, std::move(v)); return *this; }
    Value& push(Value v) { items.push_back(std::move(v)); return *this; }
};


Value vec2(Vec2 p);
Value vec3(const Vec3& p);

std::string format_double(double v, int digits);
// Doubles with 17 significant digits so they read back bit-exactly; inf and NaN become null.
void to_json(std::string& out, const Value& v);
std::string to_json(const Value& v);
// The same value for people: numbers with 10 digits, number lists as (x, y), objects as k=v.
void to_text(std::string& out, const Value& v);
// The field `key` of an object, or nullptr.
const Value* find_field(const Value& obj, const std::string& key);
Value* find_field(Value& obj, const std::string& key);

}  // namespace hlens
