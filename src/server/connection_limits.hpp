#pragma once
// How long and how much one connection to `ncvm serve` may take (server/guarded_http.hpp).
namespace ncvm::server {

struct ConnectionLimits {
  int firstRequestSeconds = 5;  // from the connection to the first byte of a request
  int idleSeconds = 2;          // between two requests on one connection
  int requestSeconds = 10;      // from a request's first byte to its last
  int requestsPerConnection = 100;
  int connectionsPerClient = 64;  // open connections of one remote address
};

}  // namespace ncvm::server
