package studio.engine.material;

/** The six materials of the scene format. */
public enum MaterialKind {
    /** Its colour, unlit: no light, no shadow. */
    FLAT,
    /** Diffuse only. */
    CHALK,
    /** Diffuse plus a white highlight. */
    PLASTIC,
    /** A highlight tinted by its colour and a tinted reflection. */
    METAL,
    /** Perfect reflection, tinted. */
    MIRROR,
    /** Refraction with an index, Fresnel reflection, total internal reflection. */
    GLASS
}
