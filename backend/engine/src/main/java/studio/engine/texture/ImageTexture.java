package studio.engine.texture;

/**
 * An image repeated over the surface: {@code scaleU} x {@code scaleV} copies per unit of the
 * surface's (u, v) (per metre on a plane; per face on a box; over the whole of a sphere), filtered by
 * trilinear mip-mapping to the footprint's size.
 */
public record ImageTexture(MipMap image, double scaleU, double scaleV) implements Texture {

    public ImageTexture {
        if (image == null) {
            throw new IllegalArgumentException("an image texture needs its image");
        }
        if (!(scaleU > 0) || !Double.isFinite(scaleU) || !(scaleV > 0) || !Double.isFinite(scaleV)) {
            throw new IllegalArgumentException("image scale must be finite and positive: " + scaleU + ", " + scaleV);
        }
    }

    /** One copy of the image per unit of (u, v). */
    public ImageTexture(MipMap image) {
        this(image, 1, 1);
    }

    @Override
    public void filtered(double u, double v, double widthU, double widthV, double metresU, double metresV,
                         boolean wrapsU, double[] out) {
        double texels = Math.max(widthU * scaleU * image.width(), widthV * scaleV * image.height());
        image.sample(u * scaleU, v * scaleV, texels, out);
    }
}
