// A small streaming JSON writer for metrics.json, `info --json` and network messages.
#pragma once

#include <string>
#include <vector>

namespace sightline {

// Builds one JSON document. Keys and values are escaped; NaN and infinity are written as null.
//
//   JsonWriter w;
//   w.BeginObject();
//   w.Key("frames"); w.Int(51);
//   w.Key("timing_ms"); w.BeginObject(); ... w.EndObject();
//   w.EndObject();
//   std::string text = w.str();
class JsonWriter {
 public:
  explicit JsonWriter(bool pretty = true) : pretty_(pretty) {}

  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  JsonWriter& Key(const std::string& key);
  JsonWriter& String(const std::string& value);
  JsonWriter& Double(double value);
  JsonWriter& Int(long long value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();
  // Inserts an already-serialised JSON value.
  JsonWriter& Raw(const std::string& json);

  const std::string& str() const { return out_; }

  static std::string Escape(const std::string& text);

 private:
  void BeforeValue();
  void NewLine();

  bool pretty_;
  std::string out_;
  // One entry per open container: number of members written so far.
  std::vector<int> counts_;
  bool after_key_ = false;
};

}  // namespace sightline
