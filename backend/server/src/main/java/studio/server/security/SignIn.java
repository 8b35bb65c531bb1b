package studio.server.security;

import java.security.Principal;

/**
 * Whether callers sign in, and what one principal may hold at once. With sign-in off (the default, a
 * studio on one's own machine) every caller is the same nobody, {@code ""}, limited only by the
 * server's own limits.
 */
public final class SignIn {

    private final boolean required;
    private final int maxJobsPerPrincipal;
    private final int maxLiveViewsPerPrincipal;

    /**
     * @param maxJobsPerPrincipal      0 for the default, given by the caller of {@link #maxJobsPerPrincipal}
     * @param maxLiveViewsPerPrincipal 0 for the default, given by the caller of {@link #maxLiveViewsPerPrincipal}
     */
    SignIn(boolean required, int maxJobsPerPrincipal, int maxLiveViewsPerPrincipal) {
        this.required = required;
        this.maxJobsPerPrincipal = maxJobsPerPrincipal;
        this.maxLiveViewsPerPrincipal = maxLiveViewsPerPrincipal;
    }

    /** Sign-in off: anyone who reaches the port may do anything. */
    public static final SignIn OFF = new SignIn(false, 0, 0);

    public boolean required() {
        return required;
    }

    /** The name a job or a live view belongs to: the signed-in principal's, or "" with sign-in off. */
    public static String principal(Principal principal) {
        return principal != null ? principal.getName() : "";
    }

    /**
     * The most render jobs one principal may have queued or running at once: unlimited with sign-in off.
     *
     * @param slots the server's running and queued places, half of which is the default
     */
    public int maxJobsPerPrincipal(int slots) {
        return limit(maxJobsPerPrincipal, slots);
    }

    /**
     * The most live views one principal may have open at once: unlimited with sign-in off.
     *
     * @param sessions the server's live views, half of which is the default
     */
    public int maxLiveViewsPerPrincipal(int sessions) {
        return limit(maxLiveViewsPerPrincipal, sessions);
    }

    private int limit(int configured, int serverWide) {
        if (!required) {
            return Integer.MAX_VALUE;
        }
        return configured > 0 ? configured : Math.max(1, serverWide / 2);
    }
}
