package studio.server.scene.gltf;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

import studio.engine.material.MaterialKind;

/** A glTF roughness's highlight: as broad as the roughness says, and no brighter in all than the default's. */
class GltfHighlightTest {

    @Test
    void theDefaultExponentKeepsTheDefaultStrength() {
        assertThat(GltfMaterials.highlight(MaterialKind.PLASTIC, 60)).isCloseTo(0.5, within(1e-12));
        assertThat(GltfMaterials.highlight(MaterialKind.METAL, 120)).isCloseTo(0.8, within(1e-12));
    }

    @Test
    void aRoughSurfacesBroadHighlightIsWeakerSoItsColourShows() {
        // roughness 0.8: exponent 2/0.64^2 - 2 = 2.88; normalised Blinn-Phong (n + 8) against the default's 68
        double n = GltfMaterials.shininess(0.8);
        assertThat(n).isCloseTo(2.8828125, within(1e-9));
        assertThat(GltfMaterials.highlight(MaterialKind.PLASTIC, n)).isCloseTo(0.5 * (n + 8) / 68, within(1e-12))
                .isLessThan(0.1);
    }

    @Test
    void aSmoothSurfacesNarrowHighlightIsStrongerButAtMostOne() {
        assertThat(GltfMaterials.highlight(MaterialKind.PLASTIC, 100)).isCloseTo(0.5 * 108 / 68, within(1e-12));
        assertThat(GltfMaterials.highlight(MaterialKind.PLASTIC, 10000)).isEqualTo(1);
    }
}
