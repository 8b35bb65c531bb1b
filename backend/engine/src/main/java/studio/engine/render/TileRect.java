package studio.engine.render;

/** A rectangle of the image rendered as one unit of work. */
public record TileRect(int x, int y, int width, int height) {

    /** Whether pixel (px, py) lies in this tile. */
    public boolean contains(int px, int py) {
        return px >= x && px < x + width && py >= y && py < y + height;
    }
}
