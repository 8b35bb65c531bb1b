import { useRef, type ChangeEvent, type ReactNode } from 'react';

/** Props of {@link ObjFileButton}. */
export interface ObjFileButtonProps {
  /** The button's text. */
  children: ReactNode;
  /** The button's accessible name, when it differs from its text. */
  ariaLabel?: string;
  /** Tooltip. */
  title: string;
  /** `data-testid` of the (hidden) file input, so tests can hand it a file. */
  testId: string;
  /** Called with the text and name of the picked file. */
  onLoad: (text: string, fileName: string) => void;
  /** Called with a readable message when the file cannot be read. */
  onError: (message: string) => void;
}

/** A button that opens the file picker for a Wavefront OBJ file (`.obj`) and hands over its text. */
export function ObjFileButton({ children, ariaLabel, title, testId, onLoad, onError }: ObjFileButtonProps) {
  const input = useRef<HTMLInputElement>(null);
  const onChange = async (event: ChangeEvent<HTMLInputElement>) => {
    const element = event.currentTarget;
    const file = element.files?.[0];
    if (!file) return;
    try {
      onLoad(await file.text(), file.name);
    } catch (error) {
      onError(`Cannot read ${file.name}: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      element.value = '';
    }
  };
  return (
    <>
      <button type="button" aria-label={ariaLabel} title={title} onClick={() => input.current?.click()}>
        {children}
      </button>
      <input ref={input} className="visually-hidden" type="file" accept=".obj,text/plain" tabIndex={-1} aria-hidden="true" data-testid={testId} onChange={onChange} />
    </>
  );
}
