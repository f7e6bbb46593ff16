#pragma once
// Whitespace tokenizer over a whole text file, for the .msh and .mesh readers (mesh_io.h).
// Every failure is an Error("load") naming the file and the line.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "framefix/core/error.h"

namespace framefix {

class TextTokens {
public:
    explicit TextTokens(const std::string& path, char comment = 0) : path_(path), comment_(comment) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error("load", path + ": cannot open the file (missing or unreadable)");
        std::ostringstream ss;
        ss << in.rdbuf();
        text_ = ss.str();
        if (text_.find_first_not_of(" \t\r\n") == std::string::npos) throw Error("load", path + ": the file is empty");
        pos_ = text_.data();
        end_ = pos_ + text_.size();
    }

    bool at_end() {
        skip();
        return pos_ >= end_;
    }
    std::string word() {
        skip();
        if (pos_ >= end_) fail("unexpected end of file (truncated?)");
        const char* start = pos_;
        while (pos_ < end_ && !is_space(*pos_)) ++pos_;
        return std::string(start, pos_);
    }
    long long integer() {
        skip();
        long long v = 0;
        const auto r = std::from_chars(pos_, end_, v);
        if (r.ec != std::errc() || (r.ptr < end_ && !is_space(*r.ptr))) fail("expected an integer, found '" + peek_word() + "'");
        pos_ = r.ptr;
        return v;
    }
    double real() {
        skip();
        double v = 0;
        const auto r = std::from_chars(pos_, end_, v);
        if (r.ec != std::errc() || (r.ptr < end_ && !is_space(*r.ptr))) fail("expected a number, found '" + peek_word() + "'");
        if (!std::isfinite(v)) fail("non-finite coordinate");
        pos_ = r.ptr;
        return v;
    }
    // A count that must fit in memory: non-negative and at most `limit`.
    int count(long long limit, const char* what) {
        const long long n = integer();
        if (n < 0 || n > limit) fail(std::string("implausible ") + what + " count " + std::to_string(n));
        return int(n);
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error("load", path_ + ", line " + std::to_string(line()) + ": " + why);
    }
    // Upper bound on any count in the file: every item takes at least two characters.
    long long max_items() const { return (long long)text_.size() / 2 + 1; }

private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
    void skip() {
        for (;;) {
            while (pos_ < end_ && is_space(*pos_)) ++pos_;
            if (comment_ && pos_ < end_ && *pos_ == comment_) {
                while (pos_ < end_ && *pos_ != '\n') ++pos_;
                continue;
            }
            return;
        }
    }
    std::string peek_word() {
        const char* p = pos_;
        while (p < end_ && !is_space(*p) && p - pos_ < 20) ++p;
        return pos_ >= end_ ? std::string("end of file") : std::string(pos_, p);
    }
    int line() const { return 1 + int(std::count(text_.data(), pos_, '\n')); }

    std::string path_;
    char comment_;
    std::string text_;
    const char* pos_ = nullptr;
    const char* end_ = nullptr;
};

}  // namespace framefix
