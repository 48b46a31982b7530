from physai_lint.cli import main

raise SystemExit(main())
