#include "api/event_adapter.hpp"

namespace ncvm::api {

EventHandler::~EventHandler() = default;

Origin EventAdapter::origin(const EventOrigin& at) const {
  return Origin{files_.name(at.file), at.line, at.n};
}

void EventAdapter::onMove(const MoveEvent& e) {
  Move m;
  m.at = origin(e.at);
  switch (e.mode) {
    case MoveMode::Rapid:
      m.kind = MoveKind::Rapid;
      break;
    case MoveMode::Linear:
      m.kind = MoveKind::Linear;
      break;
    case MoveMode::Cw:
      m.kind = MoveKind::ArcCw;
      break;
    case MoveMode::Ccw:
      m.kind = MoveKind::ArcCcw;
      break;
  }
  m.start = e.start;
  m.end = e.end;
  m.feed = e.mode == MoveMode::Rapid ? 0 : e.feed;
  m.length = e.length;
  m.time = e.time;
  m.center = e.center;
  m.plane = e.plane;
  m.probing = e.skip;
  handler_.onMove(m);
}

void EventAdapter::onDwell(const DwellEvent& e) {
  handler_.onDwell(Dwell{origin(e.at), e.time});
}

void EventAdapter::onTool(const ToolEvent& e) {
  handler_.onTool(ToolSelect{origin(e.at), e.tool, e.change});
}

void EventAdapter::onMessage(const MessageEvent& e) {
  handler_.onMessage(Message{origin(e.at), e.text, e.source});
}

void EventAdapter::onComment(const CommentEvent& e) {
  handler_.onComment(Comment{origin(e.at), e.text});
}

void EventAdapter::onAlarm(const ncvm::AlarmEvent& e) {
  handler_.onAlarm(api::AlarmEvent{origin(e.at), e.code, e.text});
}

}  // namespace ncvm::api
