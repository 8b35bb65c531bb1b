package studio.bench.accuracy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

import studio.engine.render.Film;

class ImageErrorTest {

    @Test
    void rmseOfArraysIsTheRootOfTheMeanSquaredDifference() {
        // differences 0, 0.5, 1: mean square (0 + 0.25 + 1) / 3
        assertThat(ImageError.rmse(new double[] {0, 0.5, 1}, new double[] {0, 0, 0}))
                .isCloseTo(Math.sqrt(1.25 / 3), within(1e-15));
        assertThat(ImageError.rmse(new double[] {0.3, 0.3}, new double[] {0.3, 0.3})).isZero();
    }

    @Test
    void rmseOfFilmsCountsEveryChannelOfEveryPixel() {
        Film image = new Film(2, 1), reference = new Film(2, 1);
        image.set(0, 0, 0.1, 0.2, 0.3);
        reference.set(0, 0, 0.1, 0.2, 0.6);
        image.set(1, 0, 1, 1, 1);
        reference.set(1, 0, 1, 1, 1);
        // one channel off by 0.3 among 6: sqrt(0.09 / 6)
        assertThat(ImageError.rmse(image, reference)).isCloseTo(Math.sqrt(0.09 / 6), within(1e-15));
    }

    @Test
    void rejectsImagesOfDifferentSizes() {
        assertThatThrownBy(() -> ImageError.rmse(new Film(2, 1), new Film(1, 2)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> ImageError.rmse(new double[] {1}, new double[] {1, 2}))
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void psnrHasAPeakOfOne() {
        assertThat(ImageError.psnr(1)).isCloseTo(0, within(1e-12));
        assertThat(ImageError.psnr(0.1)).isCloseTo(20, within(1e-12));
        assertThat(ImageError.psnr(0.01)).isCloseTo(40, within(1e-12));
        assertThat(ImageError.psnr(0.5)).isCloseTo(6.0206, within(1e-4));
        assertThat(ImageError.psnr(0)).isInfinite().isPositive();
        assertThatThrownBy(() -> ImageError.psnr(-0.1)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> ImageError.psnr(Double.NaN)).isInstanceOf(IllegalArgumentException.class);
    }
}
