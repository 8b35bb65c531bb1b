package studio.bench;

/**
 * How well our silhouette mask of a scene matches each peer's: the share of pixels that agree (the
 * benchmark requires {@link Masks#REQUIRED}) and, for information, the intersection over union of the
 * object pixels, which small objects on a large background cannot hide behind.
 *
 * @param coverage the share of our mask's pixels that are objects
 */
record MaskCheck(double agreementPovray, double agreementSunflow, double iouPovray, double iouSunflow,
                 double coverage) {

    static MaskCheck of(boolean[] ours, boolean[] povray, boolean[] sunflow) {
        return new MaskCheck(Masks.agreement(ours, povray), Masks.agreement(ours, sunflow),
                Masks.intersectionOverUnion(ours, povray), Masks.intersectionOverUnion(ours, sunflow),
                Masks.coverage(ours));
    }

    boolean agrees() {
        return agreementPovray >= Masks.REQUIRED && agreementSunflow >= Masks.REQUIRED;
    }
}
