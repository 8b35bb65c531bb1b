package studio.engine.render;

/** A rectangle of the image rendered as one unit of work. */
public record TileRect(int x, int y, int width, int height) {
}
