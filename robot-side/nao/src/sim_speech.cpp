#include <algorithm>
#include <sstream>

#include "sim_modules.h"

namespace touchline::nao {

namespace {
const std::vector<std::string> kLanguages = {"English", "German", "French", "Japanese",
                                             "Spanish", "Italian"};
}

SimSpeech::SimSpeech(RobotState& robot)
    : SimModule("ALTextToSpeech", "Speech (simulated: blocks 60 ms per character)."),
      robot_(robot) {
  add({"say", {{"stringToSay", ParamType::String}, {"language", ParamType::String}}, "void",
       "Says the text; blocks until spoken (60 ms per character) or stopAll.",
       [this](const Params& p) {
         if (p.size() > 1) {
           std::string lang = stringArg(p, 1);
           if (std::find(kLanguages.begin(), kLanguages.end(), lang) == kLanguages.end())
             throw CallError("language '" + lang + "' is not installed");
         }
         std::uint64_t generation = stopGeneration_;
         robot_.sleepFor(stringArg(p, 0).size() * kSecondsPerChar,
                         [this, generation] { return stopGeneration_ != generation; });
         return none();
       },
       1});
  add({"stopAll", {}, "void", "Stops all running say calls.", [this](const Params&) {
         ++stopGeneration_;
         robot_.wakeSleepers();
         return none();
       }});
  add({"getVolume", {}, "float", "Volume 0..1.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(floatValue(static_cast<float>(volume_)));
       }});
  add({"setVolume", {{"volume", ParamType::Float}}, "void", "Volume 0..1.",
       [this](const Params& p) {
         double v = numberArg(p, 0);
         if (v < 0.0 || v > 1.0) throw CallError("volume must be in 0..1");
         std::lock_guard<std::mutex> lock(mutex_);
         volume_ = v;
         return none();
       }});
  add({"getLanguage", {}, "str", "Current language.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(stringValue(language_));
       }});
  add({"setLanguage", {{"language", ParamType::String}}, "void", "One of getAvailableLanguages.",
       [this](const Params& p) {
         std::string lang = stringArg(p, 0);
         if (std::find(kLanguages.begin(), kLanguages.end(), lang) == kLanguages.end())
           throw CallError("language '" + lang + "' is not installed");
         std::lock_guard<std::mutex> lock(mutex_);
         language_ = lang;
         return none();
       }});
  for (const char* verb : {"getAvailableLanguages", "getSupportedLanguages"}) {
    add({verb, {}, "Vec<str>", "Installed languages.",
         [](const Params&) { return std::optional<Value>(stringList(kLanguages)); }});
  }
  add({"getVoice", {}, "str", "Current voice.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(stringValue(voice_));
       }});
  add({"setVoice", {{"voiceID", ParamType::String}}, "void", "Any voice name is accepted.",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         voice_ = stringArg(p, 0);
         return none();
       }});
  add({"getParameter", {{"parameter", ParamType::String}}, "float",
       "pitchShift, doubleVoice, doubleVoiceLevel, doubleVoiceTimeShift, speed.",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         auto it = parameters_.find(stringArg(p, 0));
         if (it == parameters_.end()) throw CallError("unknown parameter '" + stringArg(p, 0) + "'");
         return std::optional<Value>(floatValue(static_cast<float>(it->second)));
       }});
  add({"setParameter", {{"parameter", ParamType::String}, {"value", ParamType::Float}}, "void",
       "Sets a known parameter.", [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         auto it = parameters_.find(stringArg(p, 0));
         if (it == parameters_.end()) throw CallError("unknown parameter '" + stringArg(p, 0) + "'");
         it->second = numberArg(p, 1);
         return none();
       }});
  // Everything but say: stopAll must never wait behind the say it stops.
  markQuick({"stopAll", "getVolume", "setVolume", "getLanguage", "setLanguage",
             "getAvailableLanguages", "getSupportedLanguages", "getVoice", "setVoice",
             "getParameter", "setParameter"});
}

}  // namespace touchline::nao
