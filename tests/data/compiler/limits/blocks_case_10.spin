PUB main | x, i
  case x
    1..3:
      case x
        1..3:
          case x
            1..3:
              case x
                1..3:
                  case x
                    1..3:
                      case x
                        1..3:
                          case x
                            1..3:
                              case x
                                1..3:
                                  case x
                                    1..3:
                                      case x
                                        1..3:
                                          x := 1
