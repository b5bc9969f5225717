#pragma once
// Turns the engine's events (canon/events.hpp) into the public ones (ncvm/events.hpp) for an
// api::EventHandler: the engine's types stay out of the installed headers.
#include "canon/events.hpp"
#include "core/source.hpp"
#include "ncvm/events.hpp"

namespace ncvm::api {

class EventAdapter final : public ncvm::EventSink {
 public:
  EventAdapter(EventHandler& handler, const SourceFiles& files)
      : handler_(handler), files_(files) {}
  void onMove(const MoveEvent& e) override;
  void onDwell(const DwellEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onMessage(const MessageEvent& e) override;
  void onComment(const CommentEvent& e) override;
  void onAlarm(const ncvm::AlarmEvent& e) override;

 private:
  Origin origin(const EventOrigin& at) const;
  EventHandler& handler_;
  const SourceFiles& files_;
};

}  // namespace ncvm::api
