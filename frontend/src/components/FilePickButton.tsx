import { useRef, type ChangeEvent, type ReactNode } from 'react';

/** Props of {@link FilePickButton}. */
export interface FilePickButtonProps {
  /** The button's text. */
  children: ReactNode;
  /** The button's accessible name, when it differs from its text. */
  ariaLabel?: string;
  /** Tooltip. */
  title: string;
  /** The file types the picker offers (an `accept` attribute). */
  accept: string;
  /** Whether several files may be picked at once. */
  multiple?: boolean;
  /** `data-testid` of the (hidden) file input, so tests can hand it files. */
  testId: string;
  /** Called with the picked files. */
  onFiles: (files: File[]) => void;
}

/** A button that opens the file picker and hands over the picked files (the import's entry). */
export function FilePickButton({ children, ariaLabel, title, accept, multiple = false, testId, onFiles }: FilePickButtonProps) {
  const input = useRef<HTMLInputElement>(null);
  const onChange = (event: ChangeEvent<HTMLInputElement>) => {
    const files = [...(event.currentTarget.files ?? [])];
    event.currentTarget.value = '';
    if (files.length > 0) onFiles(files);
  };
  return (
    <>
      <button type="button" aria-label={ariaLabel} title={title} onClick={() => input.current?.click()}>
        {children}
      </button>
      <input ref={input} className="visually-hidden" type="file" accept={accept} multiple={multiple} tabIndex={-1} aria-hidden="true" data-testid={testId} onChange={onChange} />
    </>
  );
}
