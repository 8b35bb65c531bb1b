/** Props of {@link Header}. */
export interface HeaderProps {
  /** The product name shown at the top left. */
  title: string;
}

/** The page's top bar with the product name. */
export function Header({ title }: HeaderProps) {
  return (
    <header className="app-header">
      <h1>{title}</h1>
      <span className="app-header__tagline">Scene in, ray-traced image out</span>
    </header>
  );
}
