package studio.server.cluster;

/** A tile a worker has taken: which member took it and at which attempt. */
record TileClaim(String member, int attempt) {
}
