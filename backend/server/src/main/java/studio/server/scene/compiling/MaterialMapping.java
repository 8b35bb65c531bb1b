package studio.server.scene.compiling;

import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.server.scene.format.MaterialDto;

/** A material of the format onto the engine's; coefficients left out take the engine's MaterialDefaults. */
public final class MaterialMapping {

    private MaterialMapping() {
    }

    /** The engine material for a DTO; a missing material is default chalk. (The peer benchmark uses it too.) */
    public static Material of(MaterialDto m) {
        if (m == null) {
            return MaterialDefaults.of(MaterialKind.CHALK, null);
        }
        Rgb color = m.color() != null ? Colors.linear(m.color()) : null;
        if (m instanceof MaterialDto.Flat) {
            return MaterialDefaults.of(MaterialKind.FLAT, color);
        }
        if (m instanceof MaterialDto.Chalk c) {
            return MaterialDefaults.of(MaterialKind.CHALK, color, c.diffuse(), null, null, null, null);
        }
        if (m instanceof MaterialDto.Plastic p) {
            return MaterialDefaults.of(MaterialKind.PLASTIC, color, p.diffuse(), p.specular(), p.shininess(), null, null);
        }
        if (m instanceof MaterialDto.Metal x) {
            return MaterialDefaults.of(MaterialKind.METAL, color, x.diffuse(), x.specular(), x.shininess(),
                    x.reflectivity(), null);
        }
        if (m instanceof MaterialDto.Mirror x) {
            return MaterialDefaults.of(MaterialKind.MIRROR, color, null, null, null, x.reflectivity(), null);
        }
        MaterialDto.Glass g = (MaterialDto.Glass) m;
        return MaterialDefaults.of(MaterialKind.GLASS, color, null, g.specular(), g.shininess(), null, g.ior());
    }
}
