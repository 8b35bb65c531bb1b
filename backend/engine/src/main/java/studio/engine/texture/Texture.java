package studio.engine.texture;

/**
 * A colour that varies over a surface, in linear light, which a material's colour multiplies (as
 * glTF's baseColorFactor times baseColorTexture). Looked up once per shaded hit, averaged over the
 * hit's footprint in texture space, so a texture never aliases however small it appears.
 */
public sealed interface Texture permits CheckerTexture, ImageTexture {

    /**
     * Into {@code out[0..2]}: the texture's mean colour over the box centred on (u, v) of full widths
     * {@code widthU} by {@code widthV} in texture units ({@code Infinity} allowed: the mean over the
     * whole texture). {@code metresU}/{@code metresV}, {@code wrapsU}: as {@link
     * studio.engine.geometry.TextureCoordinates} has them. Allocates nothing.
     */
    void filtered(double u, double v, double widthU, double widthV, double metresU, double metresV, boolean wrapsU,
                  double[] out);
}
