package studio.server.job;

/** A finished tile as the event stream sends it: its rectangle and its pixels as a base64 PNG. */
public record TileEvent(int x, int y, int width, int height, String png, double progress) implements JobEvent {
}
